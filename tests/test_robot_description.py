"""Gazebo plugins in the robot description become the ports of the spawn_model instance."""

from __future__ import annotations

import shutil
from pathlib import Path

from conftest import ROOT

from archlog.analysis import analyse
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules

CASES = ROOT / "corpus" / "robot_description"
CAMERA_URDF = """<robot name="cam">
  <link name="base_link"/>
  <gazebo reference="base_link">
    <sensor type="camera" name="front">
      <plugin name="front_camera" filename="libgazebo_ros_camera.so">
        <robotNamespace>rover</robotNamespace>
        <cameraName>front</cameraName>
      </plugin>
    </sensor>
    <plugin name="laser" filename="libgazebo_ros_laser.so"/>
  </gazebo>
</robot>
"""


def ports(analysis, relation: str) -> list[tuple[str, str, str]]:
    return sorted((n, t if isinstance(t, str) else "?", ty) for _p, n, t, ty in analysis.store.rows(relation))


def test_an_imu_topic_set_in_xacro_is_checked_against_its_subscriber() -> None:
    buggy = analyse([CASES / "buggy"], ["bot/sim.launch"], {}, [])
    assert buggy.diagnostics.items == []
    assert [p for p in ports(buggy, "publisher") if p[0] == "/spawn_bot"] == [
        ("/spawn_bot", "/imu_raw", "sensor_msgs/Imu"), ("/spawn_bot", "/odom", "nav_msgs/Odometry")]
    assert ("/spawn_bot", "/cmd_vel", "geometry_msgs/Twist") in ports(buggy, "subscriber")
    found = Engine(load_rules([])).run(buggy.store)[1]
    assert [(f.rule.id, f.values["topic"], str(f.location.file), f.location.line) for f in found] == [
        ("AL601", "/imu/data", "bot/scripts/guard.py", 10)]  # it stops the base only on IMU messages
    assert found[0].values["near"] == "; candidates: /imu_raw"  # the xacro's topic is the candidate (AL103 steps aside)
    clean = analyse([CASES / "clean"], ["bot/sim.launch"], {}, [])  # imu_topic:=imu/data on the xacro command
    assert ("/spawn_bot", "/imu/data", "sensor_msgs/Imu") in ports(clean, "publisher")
    assert Engine(load_rules([])).run(clean.store)[1] == []


def test_urdf_textfile_plugins_namespaces_and_unknown_topics(tmp_path: Path) -> None:
    pkg = tmp_path / "cam"
    shutil.copytree(CASES / "clean" / "bot", pkg)
    (pkg / "package.xml").write_text((pkg / "package.xml").read_text().replace("<name>bot</name>", "<name>cam</name>"))
    (pkg / "urdf" / "cam.urdf").write_text(CAMERA_URDF)
    (pkg / "launch" / "cam.launch").write_text(
        "<launch><param name='robot_description' textfile='$(find cam)/urdf/cam.urdf'/>"
        "<node pkg='gazebo_ros' type='spawn_model' name='spawn' args='-urdf -param robot_description -model cam'/>"
        "<group ns='two'><param name='robot_description' textfile='$(find cam)/urdf/cam.urdf'/>"
        "<node pkg='gazebo_ros' type='spawn_model' name='spawn' "
        "args='-urdf -param robot_description -model cam2 -robot_namespace r2'/></group>"
        "<node pkg='gazebo_ros' type='spawn_model' name='orphan' args='-urdf -param missing_description'/></launch>")
    result = analyse([tmp_path], ["cam/cam.launch"], {}, [])
    camera = [("/camera_info", "sensor_msgs/CameraInfo"), ("/image_raw", "sensor_msgs/Image"),
              # image_transport's compressed, compressedDepth and theora topics, each with its reconfigure server
              *[(f"/image_raw/{transport}{suffix}", type_) for transport, packet in (
                  ("compressed", "sensor_msgs/CompressedImage"), ("compressedDepth", "sensor_msgs/CompressedImage"),
                  ("theora", "theora_image_transport/Packet"))
                for suffix, type_ in (("", packet), ("/parameter_descriptions", "dynamic_reconfigure/ConfigDescription"),
                                      ("/parameter_updates", "dynamic_reconfigure/Config"))],
              ("/parameter_descriptions", "dynamic_reconfigure/ConfigDescription"),
              ("/parameter_updates", "dynamic_reconfigure/Config")]
    assert [p for p in ports(result, "publisher") if "spawn" in p[0]] == [
        *[("/spawn", "/rover/front" + n, t) for n, t in camera], ("/spawn", "?", "sensor_msgs/LaserScan"),
        *[("/two/spawn", "/r2/front" + n, t) for n, t in camera], ("/two/spawn", "?", "sensor_msgs/LaserScan")]
    assert [p for p in ports(result, "service_server") if p[0] == "/spawn"] == [
        *[("/spawn", f"/rover/front/image_raw/{t}/set_parameters", "dynamic_reconfigure/Reconfigure")
          for t in ("compressed", "compressedDepth", "theora")],
        ("/spawn", "/rover/front/set_camera_info", "sensor_msgs/SetCameraInfo"),
        ("/spawn", "/rover/front/set_parameters", "dynamic_reconfigure/Reconfigure")]
    assert [(d.line, d.code) for d in result.diagnostics.items] == [(1, "robot-description"), (1, "port-name-unknown")]
    assert "/missing_description" in result.diagnostics.items[0].message


def test_broken_xacro_is_a_diagnostic_at_the_parameter(tmp_path: Path) -> None:
    shutil.copytree(CASES / "buggy" / "bot", tmp_path / "bot")
    (tmp_path / "bot" / "urdf" / "sensors.xacro").write_text("<robot><broken\n")
    result = analyse([tmp_path], ["bot/sim.launch"], {}, [])
    assert [(d.file, d.line, d.code) for d in result.diagnostics.items] == [
        ("bot/launch/sim.launch", 2, "robot-description")]
    assert "xacro cannot expand" in result.diagnostics.items[0].message


def test_an_include_of_a_package_not_here_is_left_out_and_the_spawner_is_partial(tmp_path: Path) -> None:
    shutil.copytree(CASES / "clean" / "bot", tmp_path / "bot")
    xacro = tmp_path / "bot" / "urdf" / "bot.urdf.xacro"
    xacro.write_text(xacro.read_text().replace('<link name="base_link"/>', '<link name="base_link"/>\n'
                                               '  <xacro:include filename="$(find vendor_lidar)/urdf/lidar.xacro"/>'))
    result = analyse([tmp_path], ["bot/sim.launch"], {}, [])
    assert [(d.file, d.line, d.code) for d in result.diagnostics.items] == [
        ("bot/urdf/bot.urdf.xacro", 5, "robot-description")]
    assert "<xacro:include> left out: package 'vendor_lidar' not found" in result.diagnostics.items[0].message
    assert ("/spawn_bot", "/imu/data", "sensor_msgs/Imu") in ports(result, "publisher")  # the rest is read
    assert list(result.store.rows("node_incomplete")) == [
        ("/spawn_bot", "its robot description was read without an include (package 'vendor_lidar' not found)")]


def test_a_description_not_read_leaves_its_spawner_partial(tmp_path: Path) -> None:
    shutil.copytree(CASES / "clean" / "bot", tmp_path / "bot")
    (tmp_path / "bot" / "urdf" / "sensors.xacro").write_text("<robot><broken\n")
    result = analyse([tmp_path], ["bot/sim.launch"], {}, [])
    assert list(result.store.rows("node_incomplete")) == [
        ("/spawn_bot", "the robot description in robot_description was not read: its gazebo plugins are unknown")]


def test_unreadable_descriptions_and_arguments_are_diagnostics(tmp_path: Path) -> None:
    shutil.copytree(CASES / "clean" / "bot", tmp_path / "bot")
    (tmp_path / "bot" / "urdf" / "other.urdf").write_text(
        "<robot name='x'><gazebo><plugin name='p' filename='libgazebo_ros_bumper.so'/></gazebo></robot>\n")
    (tmp_path / "bot" / "launch" / "bad.launch").write_text(
        "<launch><param name='robot_description' command='xacro &quot;bot.xacro'/>\n"
        "<node pkg='gazebo_ros' type='spawn_model' name='a' args='-urdf -param robot_description'/>\n"
        "<param name='other' textfile='$(find bot)/urdf/other.urdf'/>\n"
        "<node pkg='gazebo_ros' type='spawn_model' name='b' args='-urdf -param other'/>\n"
        "<node pkg='controller_manager' type='spawner' name='c' args='base &quot;arm'/></launch>\n")
    result = analyse([tmp_path], ["bot/bad.launch"], {}, [])
    assert sorted((d.line, d.severity, d.code) for d in result.diagnostics.items) == [
        (1, "note", "robot-description"), (3, "note", "plugin-no-model"), (5, "error", "launch-invalid")]


def test_legacy_macro_calls_hector_and_ros_control_plugins_and_unmodelled_plugins() -> None:
    result = analyse([CASES / "legacy"], ["rover/sim.launch"], {}, [])
    assert [(d.file, d.line, d.severity, d.code) for d in result.diagnostics.items] == [
        ("rover/urdf/rover.urdf.xacro", 6, "note", "xacro-legacy"),  # <rover_imu/> is expanded, not dropped
        ("rover/urdf/sensors.xacro", 13, "note", "plugin-no-model")]  # the plugin's file and line
    assert "libgazebo_ros_bumper.so" in result.diagnostics.items[1].message
    published = [t for n, t, _ in ports(result, "publisher") if n == "/spawn_rover"]
    assert published == ["/imu/data", "/imu/data/accel/parameter_descriptions", "/imu/data/accel/parameter_updates",
                         "/imu/data/bias", "/imu/data/rate/parameter_descriptions", "/imu/data/rate/parameter_updates",
                         "/imu/data/yaw/parameter_descriptions", "/imu/data/yaw/parameter_updates"]
    served = [t for n, t, _ in ports(result, "service_server") if n == "/spawn_rover"]
    assert served == ["/controller_manager/list_controller_types", "/controller_manager/list_controllers",
                      "/controller_manager/load_controller", "/controller_manager/reload_controller_libraries",
                      "/controller_manager/switch_controller", "/controller_manager/unload_controller",
                      "/imu/data/accel/set_parameters", "/imu/data/calibrate", "/imu/data/rate/set_parameters",
                      "/imu/data/set_accel_bias", "/imu/data/set_rate_bias", "/imu/data/yaw/set_parameters"]


def test_plugin_defaults_unknown_namespaces_and_plain_elements(tmp_path: Path) -> None:
    shutil.copytree(CASES / "legacy" / "rover", tmp_path / "rover")
    (tmp_path / "rover" / "urdf" / "rover.urdf.xacro").write_text(
        "<robot name='r' xmlns:xacro='http://www.ros.org/wiki/xacro'><link name='base_link'/><gazebo>\n"
        "<plugin name='gps' filename='libhector_gazebo_ros_gps.so'><robotNamespace>r</robotNamespace></plugin>\n"
        "<plugin name='cm' filename='libgazebo_ros_control.so'/>\n"
        "<plugin name='k' filename='libgazebo_ros_kobuki.so'/></gazebo></robot>\n")
    result = analyse([tmp_path], ["rover/sim.launch"], {}, [])
    # <link>, <gazebo> are no macros: no xacro-legacy note; ros_control without <robotNamespace> names
    # its services after the model, which is not known statically
    assert [d.code for d in result.diagnostics.items] == ["port-name-unknown"]
    published = [t for n, t, _ in ports(result, "publisher") if n == "/spawn_rover"]
    assert published[:2] == ["/joint_states", "/mobile_base/events/bumper"]
    assert {"/r/fix", "/r/fix_velocity", "/r/fix/status/parameter_updates", "/odom"} <= set(published)
    assert "/tf" not in published  # kobuki broadcasts odometry on /tf only with <publish_tf>1</publish_tf>
    served = [t for n, t, _ in ports(result, "service_server") if n == "/spawn_rover"]
    assert served.count("?") == 6  # gazebo_ros_control without <robotNamespace>: the model's name, unknown here
    assert "/r/fix/set_reference_geopose" in served
    assert ("/spawn_rover", "/mobile_base/commands/velocity", "geometry_msgs/Twist") in ports(result, "subscriber")
