"""Transform facts: what nodes broadcast (models, robot descriptions, static_transform_publisher
arguments), what they wait for, the ports created after a wait, and AL701 over them."""

from __future__ import annotations

from pathlib import Path

import yaml
from conftest import CORPUS

from archlog.analysis import analyse
from archlog.diagnostics import DiagnosticSink
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules
from archlog.system.node_models import BUILTIN_DIR, LineLoader, load_models

CASE = CORPUS / "costmap_frame_unbroadcast"


def _analyse(variant: str):
    src = CASE / variant / "src"
    return analyse([src], [str(src / "base_nav" / "launch" / "nav.launch")], {}, [])


def test_broadcasts_come_from_the_description_the_arguments_and_the_models() -> None:
    store = _analyse("clean").store
    broadcasts = {(str(n), p, c): str(i) for i, n, p, c in store.rows("tf_broadcast")}
    assert set(broadcasts) == {("/robot_state_publisher", "base_link", "laser_link"),
                               ("/robot_state_publisher", "base_link", "left_wheel"),
                               ("/map_to_odom", "map", "odom"), ("/odom_to_base", "odom", "base_link")}
    after = {(str(i), str(t)) for i, t in store.rows("tf_broadcast_after")}
    # a moving joint only once joint states arrive; a fixed joint and the static transforms at once
    assert after == {(broadcasts[("/robot_state_publisher", "base_link", "left_wheel")], "/joint_states")}
    laser = store.location(broadcasts[("/robot_state_publisher", "base_link", "laser_link")])
    # a joint of a xacro description is located in its file; a textfile description at the <param>
    assert laser is not None and laser[0].endswith("nav.launch") and laser[1] == 2
    assert {str(r[0]) for r in store.rows("tf_declared")} == {"/robot_state_publisher", "/map_to_odom",
                                                              "/odom_to_base", "/move_base"}


def test_waits_take_their_frames_from_the_parameters_and_mark_the_ports_after_them() -> None:
    store = _analyse("buggy").store
    waits = {str(i): (str(n), t, s) for i, n, t, s in store.rows("tf_wait")}
    assert sorted(waits.values()) == [("/move_base", "map", "base_footprint"), ("/move_base", "odom", "base_footprint")]
    by_frame = {v[1]: k for k, v in waits.items()}
    assert list(store.rows("tf_wait_after")) == [(by_frame["odom"], by_frame["map"])]
    names = {str(r[0]): str(r[2]) for rel in ("publisher", "subscriber", "service_server") for r in store.rows(rel)}
    marked = {(names[str(p)], str(w)) for p, w in store.rows("port_after_tf") if str(p) in names}
    assert ("/move_base/global_costmap/costmap", by_frame["map"]) in marked
    assert ("/move_base/local_costmap/inflation/parameter_updates", by_frame["odom"]) in marked
    assert ("/move_base/make_plan", by_frame["odom"]) in marked
    assert not any(name in ("/cmd_vel", "/move_base/current_goal", "/move_base_simple/goal") for name, _w in marked)


def test_blocked_ports_and_the_finding_follow_the_first_wait_that_never_ends() -> None:
    analysis = _analyse("buggy")
    ctl, findings = Engine(load_rules([])).run(analysis.store)
    blocked = {str(a.symbol.arguments[0]) for a in ctl.symbolic_atoms.by_signature("tf_blocked_port", 2)}
    marked = {str(p) for p, _w in analysis.store.rows("port_after_tf")}
    assert blocked and {f'"{p}"' for p in marked} == blocked  # every port after either costmap
    [finding] = [f for f in findings if f.rule.id == "AL701"]
    assert "base_footprint into map" in finding.message and "laser_link" in finding.message
    clean = _analyse("clean")
    ctl, findings = Engine(load_rules([])).run(clean.store)
    assert not list(ctl.symbolic_atoms.by_signature("tf_blocked_port", 2))
    assert not [f for f in findings if f.rule.id == "AL701"]


def _launch(tmp_path: Path, body: str, urdf: str = "", models: list[Path] | None = None):
    """The analysis of a one-file launch configuration (with a robot description file, if given)."""
    pkg = tmp_path / "src" / "demo"
    pkg.mkdir(parents=True)
    (pkg / "package.xml").write_text("<package format='2'><name>demo</name><version>0.1.0</version><description>d"
                                     "</description><maintainer email='a@b.c'>m</maintainer><license>MIT</license>"
                                     "</package>")
    (pkg / "robot.urdf").write_text(urdf)
    launch = pkg / "tf.launch"
    launch.write_text(f"<launch>\n{body}\n</launch>")
    return analyse([tmp_path], [str(launch)], {}, models or [])


def test_arguments_that_name_no_transform_leave_the_node_undeclared(tmp_path: Path) -> None:
    analysis = _launch(tmp_path, '<node pkg="tf2_ros" type="static_transform_publisher" name="bad" args="0 0 map"/>\n'
                       '<node pkg="move_base" type="move_base" name="move_base"/>')
    [diag] = [d for d in analysis.diagnostics.items if d.code == "tf-args"]
    assert diag.file.endswith("tf.launch") and diag.line == 2 and "'0 0 map'" in diag.message
    assert "/bad" not in {str(r[0]) for r in analysis.store.rows("tf_declared")}
    assert [str(r[0]) for r in analysis.store.rows("tf_unknown")] == ["/bad"]
    _ctl, findings = Engine(load_rules([])).run(analysis.store)
    assert not [f for f in findings if f.rule.id == "AL701"]  # /bad may broadcast anything


def test_an_after_tf_naming_no_wait_is_a_schema_error(tmp_path: Path) -> None:
    model = tmp_path / "m.yaml"
    model.write_text("package: demo\nexecutable: planner\ntf_waits:\n  - {id: costmap, target: map, source: base}\n"
                     "publishers:\n  - {name: plan, type: nav_msgs/Path, after_tf: [costmpa]}\n")
    sink = DiagnosticSink()
    [(summary, _instance)] = load_models(model, "m.yaml", sink, LineLoader)
    assert [(d.line, d.code) for d in sink.items] == [(6, "model-schema")]
    assert "costmpa" in sink.items[0].message
    assert summary.tf_waits[0].id == "costmap"
    analysis = _launch(tmp_path / "ws", '<node pkg="demo" type="planner" name="planner"/>', models=[model])
    assert "model-schema" in [d.code for d in analysis.diagnostics.items], analysis.diagnostics.items  # no crash
    assert not list(analysis.store.rows("port_after_tf")) and len(list(analysis.store.rows("tf_wait"))) == 1


SPAWN = ('<param name="robot_description" textfile="$(find demo)/robot.urdf"/>\n'
         '<node pkg="gazebo_ros" type="spawn_model" name="spawn" args="-urdf -param robot_description -model r"/>')


def test_gazebo_plugins_broadcast_what_their_model_says(tmp_path: Path) -> None:
    drive = ('<robot name="r"><link name="chassis"/><gazebo><plugin name="d" filename="libgazebo_ros_diff_drive.so">'
             '<robotBaseFrame>chassis</robotBaseFrame></plugin></gazebo>'
             '<gazebo><plugin name="i" filename="libgazebo_ros_imu.so"><topicName>imu</topicName></plugin></gazebo>'
             '</robot>')
    store = _launch(tmp_path, SPAWN, drive).store
    assert [(str(n), p, c) for _i, n, p, c in store.rows("tf_broadcast")] == [("/spawn", "odom", "chassis")]
    assert [str(r[0]) for r in store.rows("tf_declared")] == ["/spawn"]


def test_a_plugin_whose_broadcasts_are_not_modelled_leaves_spawn_model_undeclared(tmp_path: Path) -> None:
    other = ('<robot name="r"><gazebo><plugin name="s" filename="libgazebo_ros_skid_steer_drive.so"/></gazebo>'
             '</robot>')
    store = _launch(tmp_path, SPAWN, other).store
    assert list(store.rows("tf_broadcast")) == [] and list(store.rows("tf_declared")) == []
    assert [str(r[0]) for r in store.rows("tf_unknown")] == ["/spawn"]


def test_a_source_read_instead_of_the_model_keeps_the_models_marks(tmp_path: Path) -> None:
    """move_base read from source (every port of the model, so the source is used): the ports the
    model marks as created after a wait keep that mark, matched by kind and name."""
    model = yaml.safe_load((BUILTIN_DIR / "move_base.yaml").read_text())["models"][0]
    calls = [f"rospy.Publisher({p['name']!r}, Empty, queue_size=1)" for p in model["publishers"]] + \
        [f"rospy.Subscriber({p['name']!r}, Empty, callback)" for p in model["subscribers"]] + \
        [f"rospy.Service({p['name']!r}, Empty, callback)" for p in model["services"]] + \
        ["actionlib.SimpleActionServer('move_base', MoveBaseAction, callback, False)"]
    pkg = tmp_path / "src" / "move_base"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "package.xml").write_text("<package format='2'><name>move_base</name><version>1.0.0</version>"
                                     "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
                                     "<license>BSD</license></package>")
    (pkg / "CMakeLists.txt").write_text("cmake_minimum_required(VERSION 3.0.2)\nproject(move_base)\n"
                                        "catkin_install_python(PROGRAMS scripts/move_base "
                                        "DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})\n")
    (pkg / "scripts" / "move_base").write_text(
        "#!/usr/bin/env python3\nimport actionlib\nimport rospy\nfrom move_base_msgs.msg import MoveBaseAction\n"
        "from std_msgs.msg import Empty\n\n\ndef callback(*_args):\n    pass\n\n\nrospy.init_node('move_base')\n"
        + "\n".join(calls) + "\nrospy.spin()\n")
    launch = pkg / "nav.launch"
    launch.write_text('<launch><node pkg="move_base" type="move_base" name="move_base"/></launch>')
    store = analyse([tmp_path], [str(launch)], {}, []).store
    assert list(store.rows("node_source")) == [("/move_base", "python")]
    names = {str(r[0]): str(r[2]) for rel in ("publisher", "service_server") for r in store.rows(rel)}
    marked = {names[str(p)] for p, _w in store.rows("port_after_tf") if str(p) in names}
    assert {"/move_base/global_costmap/costmap", "/move_base/make_plan", "/move_base/status"} <= marked
    assert "/cmd_vel" in names.values() and "/cmd_vel" not in marked
