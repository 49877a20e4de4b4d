"""Node models: shipped models for nodes without source, user models, external instances."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from archlog.analysis import analyse
from archlog.diagnostics import DiagnosticSink
from archlog.extract.qos import PRESETS
from archlog.queries.session import Session
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules
from archlog.system.node_models import BUILTIN_DIR, load_models, released

PACKAGE_XML = ("<package format='2'><name>{}</name><version>0.1.0</version><description>d</description>"
               "<maintainer email='dev@example.com'>m</maintainer><license>MIT</license></package>")
CLIENT = """#!/usr/bin/env python3
import rospy
from nav_msgs.srv import GetMap
from sensor_msgs.msg import LaserScan
rospy.init_node('planner')
rospy.ServiceProxy('static_map', GetMap)
rospy.Subscriber('scan', LaserScan, print)
"""


def workspace(tmp_path: Path, launch: str) -> Path:
    pkg = tmp_path / "src" / "demo"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "package.xml").write_text(PACKAGE_XML.format("demo"))
    (pkg / "scripts" / "planner.py").write_text(CLIENT)
    (pkg / "scripts" / "planner.py").chmod(0o755)
    (pkg / "demo.launch").write_text(launch)
    return pkg / "demo.launch"


def findings(tmp_path: Path, launch: Path, models: list[Path]) -> tuple[list, DiagnosticSink]:
    analysis = analyse([tmp_path], [str(launch)], {}, models)
    return Engine(load_rules([])).run(analysis.store)[1], analysis.diagnostics


def test_shipped_model_provides_map_server_service(tmp_path: Path) -> None:
    with_server = workspace(tmp_path, "<launch><node pkg='map_server' type='map_server' name='map_server'/>"
                                      "<node pkg='demo' type='planner.py' name='planner'/></launch>")
    result, diags = findings(tmp_path, with_server, [])
    assert [f.rule.id for f in result] == [] and diags.items == []
    with_server.write_text("<launch><node pkg='demo' type='planner.py' name='planner'/></launch>")
    result, _ = findings(tmp_path, with_server, [])
    assert [(f.rule.id, f.values["service"]) for f in result] == [("AL201", "/static_map")]


def test_model_reads_parameters_and_declares_external_instances(tmp_path: Path) -> None:
    launch = workspace(tmp_path, "<launch><param name='laser/topic' value='scan'/>"
                                 "<node pkg='demo' type='planner.py' name='planner'/>"
                                 "<node pkg='laser_vendor' type='driver' name='laser'/></launch>")
    model = tmp_path / "laser.yaml"
    model.write_text("models:\n  - package: laser_vendor\n    executable: driver\n    publishers:\n"
                     "      - {name: {param: ~topic, default: laser_scan}, type: sensor_msgs/LaserScan}\n"
                     "  - instance: /rviz\n    subscribers:\n      - {name: /scan, type: sensor_msgs/LaserScan}\n")
    analysis = analyse([tmp_path], [str(launch)], {}, [model])
    pubs = {(n, t) for _p, n, t, _ty in analysis.store.rows("publisher")}
    subs = {(n, t) for _p, n, t, _ty in analysis.store.rows("subscriber")}
    assert ("/laser", "/scan") in pubs
    assert {("/planner", "/scan"), ("/rviz", "/scan")} <= subs
    assert analysis.store.location([p for p, n, _t, _ty in analysis.store.rows("publisher") if n == "/laser"][0]) \
        == ("laser.yaml", 5, 0)


def test_node_without_source_or_model_is_reported_once(tmp_path: Path) -> None:
    launch = workspace(tmp_path, "<launch><node pkg='mystery' type='x' name='a'/><node pkg='mystery' type='x' "
                                 "name='b'/><node pkg='demo' type='planner.py' name='planner'/></launch>")
    _result, diags = findings(tmp_path, launch, [])
    assert [d.code for d in diags.items] == ["no-model"]


def test_invalid_model_files_are_diagnostics(tmp_path: Path) -> None:
    broken = tmp_path / "broken.yaml"
    broken.write_text("package: x\nexecutable: y\npublishers:\n  - {name: a\n")
    incomplete = tmp_path / "incomplete.yaml"
    incomplete.write_text("package: x\nexecutable: y\npublishers:\n  - {name: a}\n")
    sink = DiagnosticSink()
    assert load_models(broken, "broken.yaml", sink) == []
    assert load_models(incomplete, "incomplete.yaml", sink) == []
    assert [(d.file, d.line, d.code) for d in sink.items] == [("broken.yaml", 5, "model-yaml"),
                                                             ("incomplete.yaml", 4, "model-schema")]
    assert "publishers/0: 'type' is a required property" in sink.items[1].message


def test_model_ports_that_exist_only_under_a_parameter(tmp_path: Path) -> None:
    launch = workspace(tmp_path, "<launch><node pkg='odom_vendor' type='fuser' name='fuser'>"
                                 "<param name='publish_tf' value='false'/></node>"
                                 "<node pkg='odom_vendor' type='fuser' name='fuser2'/></launch>")
    model = tmp_path / "fuser.yaml"
    model.write_text("package: odom_vendor\nexecutable: fuser\npublishers:\n"
                     "  - {name: odom, type: nav_msgs/Odometry}\n"
                     "  - {name: /tf, type: tf2_msgs/TFMessage, if: {param: ~publish_tf, default: true}}\n")
    result = analyse([tmp_path], [str(launch)], {}, [model])
    pubs = sorted((n, t) for _p, n, t, _ty in result.store.rows("publisher"))
    assert pubs == [("/fuser", "/odom"), ("/fuser2", "/odom"), ("/fuser2", "/tf")]


def test_shipped_models_are_valid() -> None:
    from archlog.system.node_models import BUILTIN_DIR

    for path in sorted(BUILTIN_DIR.glob("*.yaml")):
        sink = DiagnosticSink()
        assert load_models(path, path.name, sink) and sink.items == [], path.name


def test_twist_mux_inputs_come_from_its_topic_list(tmp_path: Path) -> None:
    launch = workspace(tmp_path, """<launch>
  <node pkg="twist_mux" type="twist_mux" name="twist_mux">
    <rosparam>
      topics:
        - {name: joystick, topic: joy_vel, timeout: 0.5, priority: 100}
        - {name: navigation, topic: nav_vel, timeout: 0.5, priority: 10}
      locks:
        - {name: e_stop, topic: e_stop, timeout: 0.0, priority: 255}
    </rosparam>
  </node>
  <node pkg="twist_mux" type="twist_mux" name="bare_mux"/>
</launch>""")
    result = analyse([tmp_path], [str(launch)], {}, [])
    subs = sorted((n, t if isinstance(t, str) else "?", ty) for _p, n, t, ty in result.store.rows("subscriber"))
    assert subs == [("/bare_mux", "?", "geometry_msgs/Twist"), ("/bare_mux", "?", "std_msgs/Bool"),
                    ("/twist_mux", "/e_stop", "std_msgs/Bool"), ("/twist_mux", "/joy_vel", "geometry_msgs/Twist"),
                    ("/twist_mux", "/nav_vel", "geometry_msgs/Twist")]


def test_robot_localization_inputs_exist_only_when_configured(tmp_path: Path) -> None:
    launch = workspace(tmp_path, "<launch><node pkg='robot_localization' type='ekf_localization_node' name='ekf'>"
                                 "<param name='odom0' value='wheel/odom'/><param name='imu0' value='imu/data'/>"
                                 "</node></launch>")
    result = analyse([tmp_path], [str(launch)], {}, [])
    subs = sorted(t for _p, _n, t, _ty in result.store.rows("subscriber"))
    assert subs == ["/imu/data", "/set_pose", "/tf", "/tf_static", "/wheel/odom"]
    dangling = Session(result.store, load_rules([])).query("dangling_sub(_, _, T, _)")
    # /set_pose is optional (a reset users may send), the configured inputs are not
    assert sorted(row[0] for row in dangling.rows) == ["/imu/data", "/wheel/odom"]


def test_model_marked_incomplete_makes_its_node_opaque(tmp_path: Path) -> None:
    launch = workspace(tmp_path, "<launch><node pkg='rosbag' type='play' name='play' args='run.bag'/>"
                                 "<node pkg='demo' type='planner.py' name='planner'/></launch>")
    result = analyse([tmp_path], [str(launch)], {}, [])
    assert [n for n, _reason in result.store.rows("node_incomplete")] == ["/play"]



def test_relay_topics_come_from_each_instance_command_line(tmp_path: Path) -> None:
    """topic_tools' model names its ports from the arguments (`{argv: "{N}"}`, `{argv_from: N}`), per
    instance, remapping words left out (and applied); a relay's input has whatever type it carries, its output
    the type of its input's publishers (none here: unknown), transform's output the type it is given; an argument
    that is not given leaves the name unknown, and the default output name is built from the input's."""
    launch = workspace(tmp_path, """<launch>
  <node pkg="topic_tools" type="mux" name="mux" ns="robot" args="cmd_vel joy_vel /nav_vel joy_vel:=joy"/>
  <node pkg="topic_tools" type="transform" name="len" args="/chatter /chatter_len std_msgs/UInt32 'len(m.data)'"/>
  <node pkg="topic_tools" type="throttle" name="throttle" args="messages scan 2.0"/>
  <node pkg="topic_tools" type="relay" name="bare"/>
</launch>""")
    result = analyse([tmp_path], [str(launch)], {}, [])
    ports = sorted((rel, n, t if isinstance(t, str) else "?", ty if isinstance(ty, str) else "*")
                   for rel in ("publisher", "subscriber", "service_server") for _p, n, t, ty in result.store.rows(rel)
                   if rel != "service_server" or "/mux/" not in t)
    assert ports == [("publisher", "/bare", "?", "*"), ("publisher", "/len", "/chatter_len", "std_msgs/UInt32"),
                     ("publisher", "/robot/mux", "/robot/cmd_vel", "*"),
                     ("publisher", "/robot/mux", "/robot/mux/selected", "std_msgs/String"),
                     ("publisher", "/throttle", "/scan_throttle", "*"),
                     ("service_server", "/robot/mux", "/robot/cmd_vel_select", "topic_tools/MuxSelect"),
                     ("subscriber", "/bare", "?", "*"), ("subscriber", "/len", "/chatter", "*"),
                     ("subscriber", "/robot/mux", "/nav_vel", "*"), ("subscriber", "/robot/mux", "/robot/joy", "*"),
                     ("subscriber", "/throttle", "/scan", "*")]


def test_command_line_names_in_a_model_are_checked(tmp_path: Path) -> None:
    model = tmp_path / "m.yaml"
    model.write_text("package: x\nexecutable: y\nsubscribers:\n  - {name: {argv: in}, type: '*'}\n"
                     "  - {name: {argv_from: 0}, type: '*'}\n  - {name: {argv: '{1}'}, type: {argv: '{2}_x'}}\n")
    sink = DiagnosticSink()
    assert load_models(model, "m.yaml", sink) == []
    assert [(d.line, d.code) for d in sink.items] == [(4, "model-schema")]
    model.write_text("package: x\nexecutable: y\nsubscribers:\n  - {name: {argv: '{1}', default: '{2}'}, type: '*'}\n")
    (summary, _instance), = load_models(model, "m.yaml", sink)
    assert summary.ports == [] and len(summary.argv_ports) == 1


def test_spawned_controllers_are_instances_of_their_type_models(tmp_path: Path) -> None:
    launch = workspace(tmp_path, """<launch>
  <group ns="base">
    <rosparam>
      joint_state_controller: {type: joint_state_controller/JointStateController, publish_rate: 50}
      mobile_base_controller: {type: diff_drive_controller/DiffDriveController, left_wheel: l, right_wheel: r}
    </rosparam>
    <node pkg="controller_manager" type="spawner" name="spawner"
          args="--shutdown-timeout 3 joint_state_controller mobile_base_controller missing_controller"/>
  </group>
</launch>""")
    result = analyse([tmp_path], [str(launch)], {}, [])
    assert sorted(n for n, *_ in result.store.rows("node")) == [
        "/base/joint_state_controller", "/base/mobile_base_controller", "/base/spawner"]
    pubs = sorted((n, t) for _p, n, t, _ty in result.store.rows("publisher") if "parameter_" not in t)
    assert pubs == [("/base/joint_state_controller", "/base/joint_states"),
                    ("/base/mobile_base_controller", "/base/mobile_base_controller/odom"),
                    ("/base/mobile_base_controller", "/tf")]
    assert [t for _p, _n, t, _ty in result.store.rows("subscriber")] == ["/base/mobile_base_controller/cmd_vel"]
    assert [(d.code, "/base/missing_controller/type" in d.message) for d in result.diagnostics.items] == [
        ("controller-type", True)]


def test_spawner_given_a_yaml_file_loads_it_and_spawns_its_controllers(tmp_path: Path) -> None:
    launch = workspace(tmp_path, """<launch>
  <group ns="base">
    <node pkg="controller_manager" type="spawner" name="spawner"
          args="--shutdown-timeout 1 $(find demo)/config/controllers.yaml $(find demo)/config/missing.yaml"/>
  </group>
</launch>""")
    (launch.parent / "config").mkdir()
    (launch.parent / "config" / "controllers.yaml").write_text(
        "joint_state_controller: {type: joint_state_controller/JointStateController, publish_rate: 50}\n"
        "mobile_base_controller: {type: diff_drive_controller/DiffDriveController, left_wheel: l}\n"
        "gains: {p: 1.0}\nrate: 10\n")
    result = analyse([tmp_path], [str(launch)], {}, [])
    assert sorted(n for n, *_ in result.store.rows("node")) == [
        "/base/joint_state_controller", "/base/mobile_base_controller", "/base/spawner"]
    assert [t for _p, _n, t, _ty in result.store.rows("subscriber")] == ["/base/mobile_base_controller/cmd_vel"]
    params = {name: value for name, value, _elem in result.store.rows("param")}
    assert (params["/base/mobile_base_controller/left_wheel"], params["/base/gains/p"], params["/base/rate"]) == (
        "l", "1.0", "10")
    assert [d.code for d in result.diagnostics.items] == ["not-a-file"]


def test_ros2_spawner_gives_its_controllers_the_parameters_of_its_param_file(tmp_path: Path) -> None:
    """ROS 2: a controller is a node named after it in the controller manager's namespace; --param-file
    gives it parameters (here use_stamped_vel, which decides its input topic), the type comes from -t,
    the file or the controller manager's NAME.type, and a spawner without a name calls itself
    spawner_<first controller>."""
    (tmp_path / "drive.yaml").write_text("drive:\n  ros__parameters:\n    use_stamped_vel: false\n"
                                         "    wheel_radius: 0.1\nother:\n  ros__parameters:\n    rate: 5\n")
    (tmp_path / "typed.yaml").write_text("/**:\n  ros__parameters:\n    type: diff_drive_controller/DiffDriveController\n")
    launch = tmp_path / "base.launch.py"
    launch.write_text(f"""from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    spawn = lambda *args: Node(package="controller_manager", executable="spawner", namespace="robot", arguments=list(args))
    return LaunchDescription([
        Node(package="controller_manager", executable="ros2_control_node", namespace="robot",
             parameters=[{{"drive.type": "diff_drive_controller/DiffDriveController"}}]),
        spawn("drive", "--param-file", "{tmp_path}/drive.yaml"),
        spawn("stamped", "-t", "diff_drive_controller/DiffDriveController", "-c", "/robot/controller_manager"),
        spawn("wildcard", "-p", "{tmp_path}/typed.yaml"),
        spawn("untyped"),
        spawn("unread", "-p", "{tmp_path}/missing.yaml"),
    ])
""")
    result = analyse([tmp_path], [str(launch)], {}, [])
    nodes = sorted(n for n, *_ in result.store.rows("node"))
    assert nodes == ["/robot/controller_manager", "/robot/drive", "/robot/spawner_drive", "/robot/spawner_stamped",
                     "/robot/spawner_unread", "/robot/spawner_untyped", "/robot/spawner_wildcard",
                     "/robot/stamped", "/robot/wildcard"]
    subs = sorted((n, t, ty) for _p, n, t, ty in result.store.rows("subscriber"))
    assert subs == [("/robot/drive", "/robot/drive/cmd_vel_unstamped", "geometry_msgs/msg/Twist"),
                    ("/robot/stamped", "/robot/stamped/cmd_vel", "geometry_msgs/msg/TwistStamped"),
                    ("/robot/wildcard", "/robot/wildcard/cmd_vel", "geometry_msgs/msg/TwistStamped")]
    params = {name: value for name, value, _elem in result.store.rows("param")}
    assert params["/robot/drive/wheel_radius"] == "0.1" and "/robot/other/rate" not in params
    codes = sorted((d.code, d.message.split(":")[0]) for d in result.diagnostics.items)
    assert codes == [("controller-type", "spawner loads /robot/unread into /robot/controller_manager, but its type "
                      "(PKG/Class) is not given"),
                     ("controller-type", "spawner loads /robot/untyped into /robot/controller_manager, but its type "
                      "(PKG/Class) is not given"),
                     ("not-a-file", "spawner's parameter file not read")]


def test_a_ros2_models_parameters_are_the_nodes_own(tmp_path: Path) -> None:
    """A ROS 2 model names parameters without `~` (nav2_amcl's `tf_broadcast`, its `scan_topic`): every
    ROS 2 parameter is a node's own, so they are read under the node's name, not its namespace."""
    launch = tmp_path / "amcl.launch.py"
    launch.write_text("""from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package="nav2_amcl", executable="amcl", name="amcl", namespace="robot",
                                   parameters=[{"tf_broadcast": False, "scan_topic": "front/scan"}])])
""")
    result = analyse([tmp_path], [str(launch)], {}, [])
    assert "/tf" not in {t for _p, _n, t, _ty in result.store.rows("publisher")}
    assert "/robot/front/scan" in {t for _p, _n, t, _ty in result.store.rows("subscriber")}
    reads = {key for _p, _n, key, _v in result.store.rows("param_read")}
    assert "/robot/amcl/tf_broadcast" in reads and "/robot/tf_broadcast" not in reads


def test_ros2_model_ports_carry_qos(tmp_path: Path) -> None:
    model = tmp_path / "lidar.yaml"
    model.write_text("package: lidar\nexecutable: driver\npublishers:\n"
                     "  - {name: scan, type: sensor_msgs/msg/LaserScan, qos: sensor_data}\n"
                     "  - {name: map, type: nav_msgs/msg/OccupancyGrid,\n"
                     "     qos: {durability: transient_local, depth: 1, deadline: 0.5}}\n")
    sink = DiagnosticSink()
    [(summary, _instance)] = load_models(model, "lidar.yaml", sink)
    scan, latched = summary.ports
    assert dict(scan.qos) == {"profile": "sensor_data", "history": "keep_last", "depth": "5",
                              "reliability": "best_effort", "durability": "volatile"}
    assert dict(latched.qos) == {"history": "keep_last", "depth": "1", "reliability": "reliable",
                                 "durability": "transient_local", "deadline": "0.5"}
    model.write_text("package: lidar\nexecutable: driver\npublishers:\n"
                     "  - {name: bad, type: std_msgs/msg/Empty, qos: {reliability: sometimes}}\n")
    assert load_models(model, "lidar.yaml", sink) == []
    assert [(d.line, d.code) for d in sink.items] == [(4, "model-schema")]


def test_model_schema_names_every_qos_preset() -> None:
    schema = json.loads((BUILTIN_DIR / "model.schema.json").read_text())
    assert set(schema["$defs"]["preset"]["enum"]) == set(PRESETS) - {"unknown"}


def _map_server_source(tmp_path: Path, body: str, version: str = "1.17.0") -> Path:
    """map_server's source at `version` (1.17.0: of the release lines archlog's model describes)."""
    pkg = tmp_path / "src" / "map_server"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "package.xml").write_text(PACKAGE_XML.format("map_server").replace("0.1.0", version))
    (pkg / "scripts" / "map_server").write_text("#!/usr/bin/env python3\nimport rospy\nfrom nav_msgs.msg import "
                                                "OccupancyGrid\nfrom nav_msgs.srv import GetMap\n"
                                                "rospy.init_node('map_server')\n" + body)
    (pkg / "scripts" / "map_server").chmod(0o755)
    return workspace(tmp_path, "<launch><node pkg='map_server' type='map_server' name='map_server'/></launch>")


def test_a_source_resolving_fewer_ports_than_the_shipped_model_does_not_win(tmp_path: Path) -> None:
    """Read incompletely (a name not known, code in a library not read), a source does not hide
    archlog's model: the model's ports are used, and where they disagree a model-drift note says so."""
    launch = _map_server_source(tmp_path, "rospy.Publisher('grid', OccupancyGrid)\n"
                                          "rospy.Service(rospy.get_name() + compute(), GetMap, print)\n")
    analysis = analyse([tmp_path], [str(launch)], {}, [])
    # (not change_map: the model has it since navigation 1.17.2, and this package is 1.17.0)
    assert {t for _p, _n, t, _ty in analysis.store.rows("service_server")} == {"/static_map"}
    assert {t for _p, _n, t, _ty in analysis.store.rows("publisher")} == {"/map", "/map_metadata"}
    drift = [d for d in analysis.diagnostics.items if d.code == "model-drift"]
    assert len(drift) == 1 and "publisher grid" in drift[0].message and "the model is used" in drift[0].message


def test_a_source_of_another_release_than_the_model_describes_wins(tmp_path: Path) -> None:
    """The same incomplete source at a release outside the model's release lines (its `distros`): the model
    describes another release of the node, so the source is used, and the note says why. The model only
    names what the source has without a name: a GetMap service, not the publishers the source names itself."""
    launch = _map_server_source(tmp_path, "rospy.Publisher('grid', OccupancyGrid)\n"
                                          "rospy.Service(rospy.get_name() + compute(), GetMap, print)\n", "2.3.0")
    analysis = analyse([tmp_path], [str(launch)], {}, [])
    assert {t for _p, _n, t, _ty in analysis.store.rows("publisher")} == {"/grid"}
    services = {t if isinstance(t, str) else t.expr for _p, _n, t, _ty in analysis.store.rows("service_server")}
    assert services == {"rospy.get_name() + compute()", "/static_map"}
    drift = [d for d in analysis.diagnostics.items if d.code == "model-drift"]
    assert len(drift) == 1 and "the source is used (the model describes release line 1.14, 1.15, 1.16, 1.17, " \
        "the source is 2.3.0)" in drift[0].message


def test_a_source_resolving_as_many_ports_wins_and_its_drift_is_noted(tmp_path: Path) -> None:
    launch = _map_server_source(tmp_path, "".join(f"rospy.Publisher('{t}', OccupancyGrid)\n"
                                                  for t in ("map", "map_metadata", "grid", "costs")))
    analysis = analyse([tmp_path], [str(launch)], {}, [])
    assert {t for _p, _n, t, _ty in analysis.store.rows("publisher")} == {"/map", "/map_metadata", "/grid", "/costs"}
    assert analysis.store.rows("service_server") == []
    drift = [d for d in analysis.diagnostics.items if d.code == "model-drift"]
    assert len(drift) == 1 and "service server static_map" in drift[0].message and "source is used" in drift[0].message


def test_a_port_since_a_release_exists_from_it_on_in_its_release_line() -> None:
    assert released("1.17.2", "1.17.2") and released("1.18.0", "1.17.2") and released("2.0", "1.17.2")
    assert not released("1.16.7", "1.17.2") and not released("1.17.1", "1.17.2")
    backported = ["1.14.9", "1.17.2"]  # move_base's recovery_status: noetic's, and kinetic's backport
    assert [released(v, backported) for v in ("1.14.2", "1.14.9", "1.14.10", "1.16.7", "1.17.1", "1.17.3")] == \
        [False, True, True, False, False, True]
    assert released(None, "9.0")  # the version is not known: the model describes the newest release


def _navigation(tmp_path: Path, version: str) -> Path:
    """navigation's amcl, map_server and move_base at `version` (package.xml only: the models are used)."""
    for pkg in ("amcl", "map_server", "move_base"):
        (tmp_path / "src" / pkg).mkdir(parents=True)
        (tmp_path / "src" / pkg / "package.xml").write_text(PACKAGE_XML.format(pkg).replace("0.1.0", version))
    return workspace(tmp_path, "<launch><node pkg='amcl' type='amcl' name='amcl'/>"
                               "<node pkg='map_server' type='map_server' name='map_server'/>"
                               "<node pkg='move_base' type='move_base' name='move_base'/></launch>")


@pytest.mark.parametrize(("version", "present"), [
    ("1.14.2", set()), ("1.14.9", {"/move_base/recovery_status"}), ("1.16.7", {"/diagnostics"}),
    ("1.17.2", {"/diagnostics", "/change_map", "/move_base/recovery_status"})])
def test_model_ports_follow_the_version_of_the_package_the_workspace_holds(tmp_path: Path, version: str,
                                                                          present: set[str]) -> None:
    analysis = analyse([tmp_path], [str(_navigation(tmp_path, version))], {}, [])
    names = {t for rel in ("publisher", "service_server") for _p, _n, t, _ty in analysis.store.rows(rel)}
    assert names & {"/diagnostics", "/change_map", "/move_base/recovery_status"} == present
    assert {"/amcl_pose", "/static_map", "/move_base/current_goal"} <= names


@pytest.mark.parametrize(("distro", "present"), [
    ("kinetic", {"/move_base/recovery_status"}), ("melodic", {"/diagnostics"}),
    ("noetic", {"/diagnostics", "/change_map", "/move_base/recovery_status"}),
    (None, {"/diagnostics", "/change_map", "/move_base/recovery_status"})])
def test_without_the_package_the_ros_distro_gives_its_release_line(tmp_path: Path, distro: str | None,
                                                                  present: set[str],
                                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    """navigation is neither in the workspace nor installed: the newest release of the line the model gives
    for ROS_DISTRO is checked (kinetic's 1.14.x has the backported recovery_status); unknown, all are kept."""
    monkeypatch.delenv("ROS_DISTRO", raising=False)
    launch = workspace(tmp_path, "<launch><node pkg='amcl' type='amcl' name='amcl'/>"
                                 "<node pkg='map_server' type='map_server' name='map_server'/>"
                                 "<node pkg='move_base' type='move_base' name='move_base'/></launch>")
    analysis = analyse([tmp_path], [str(launch)], {}, [], env={"ROS_DISTRO": distro} if distro else {})
    names = {t for rel in ("publisher", "service_server") for _p, _n, t, _ty in analysis.store.rows(rel)}
    assert names & {"/diagnostics", "/change_map", "/move_base/recovery_status"} == present


def test_since_must_be_a_version_string(tmp_path: Path) -> None:
    model = tmp_path / "m.yaml"
    model.write_text("package: demo\nexecutable: d\npublishers:\n  - {name: out, type: std_msgs/Empty, since: 1.17}\n")
    sink = DiagnosticSink()
    assert load_models(model, "m.yaml", sink) == []
    assert [(d.line, d.code) for d in sink.items] == [(4, "model-schema")] and "since" in sink.items[0].message


def test_a_model_port_that_exists_only_with_a_command_line_flag(tmp_path: Path) -> None:
    launch = workspace(tmp_path, "<launch><node pkg='amcl' type='amcl' name='live'/>"
                                 "<node pkg='amcl' type='amcl' name='replay' args='--run-from-bag run.bag'/>"
                                 "<node pkg='amcl' type='amcl' name='remapped' args='x:=--run-from-bag'/></launch>")
    analysis = analyse([tmp_path], [str(launch)], {}, [])
    scans = sorted((n, t) for _p, n, t, _ty in analysis.store.rows("publisher") if t.endswith("base_scan"))
    assert scans == [("/replay", "/base_scan")]


def test_only_a_subscriber_can_be_optional(tmp_path: Path) -> None:
    model = tmp_path / "m.yaml"
    model.write_text("package: demo\nexecutable: d\npublishers:\n  - {name: out, type: std_msgs/Empty, optional: true}\n"
                     "subscribers:\n  - {name: reset, type: std_msgs/Empty, optional: true}\n")
    sink = DiagnosticSink()
    [(summary, _instance)] = load_models(model, "m.yaml", sink)
    assert [(p.kind, p.name, p.optional) for p in summary.ports] == [("subscriber", "reset", True)]
    assert [(d.line, d.code) for d in sink.items] == [(4, "model-schema")] and "optional" in sink.items[0].message


def test_a_source_read_gets_the_optional_marks_of_the_shipped_model(tmp_path: Path) -> None:
    """amcl read from (a stand-in) source that resolves more ports than the model: the source is used,
    and its initialpose subscriber is optional as the model says."""
    pkg = tmp_path / "src" / "amcl"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "package.xml").write_text(PACKAGE_XML.format("amcl"))
    outputs = "".join(f"rospy.Publisher('out{i}', PoseArray)\n" for i in range(20))
    (pkg / "scripts" / "amcl").write_text("#!/usr/bin/env python3\nimport rospy\nfrom geometry_msgs.msg import "
                                          "PoseArray, PoseWithCovarianceStamped\nrospy.init_node('amcl')\n"
                                          "rospy.Subscriber('initialpose', PoseWithCovarianceStamped, print)\n"
                                          "rospy.Subscriber('scan', PoseArray, print)\n" + outputs)
    (pkg / "scripts" / "amcl").chmod(0o755)
    launch = workspace(tmp_path, "<launch><node pkg='amcl' type='amcl' name='amcl'/></launch>")
    analysis = analyse([tmp_path], [str(launch)], {}, [])
    assert ("/amcl", "python") in analysis.store.rows("node_source")
    optional = {p for (p,) in analysis.store.rows("optional_port")}
    assert {t for p, _n, t, _ty in analysis.store.rows("subscriber") if p in optional} == {"/initialpose"}
