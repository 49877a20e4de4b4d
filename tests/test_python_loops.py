"""Python ports made in loops and comprehensions (issue 17): the corpus system sync_input_list
(a list parameter the launch file sets, or leaves unset), budgets, and where a list parameter's
element cannot stand (a type, a default)."""

from __future__ import annotations

import shutil
from pathlib import Path

from conftest import CORPUS

from archlog import budget
from archlog.analysis import Analysis, analyse
from archlog.diagnostics import DiagnosticSink
from archlog.extract.python.node import extract_python
from archlog.values import Concat, Unknown

SYSTEM = CORPUS / "sync_input_list" / "clean"
LAUNCH = ["stereo_saver/launch/rig.launch"]


def rows(analysis: Analysis, relation: str) -> list[tuple[object, ...]]:
    return list(analysis.store.rows(relation))


def subscribed(analysis: Analysis, node: str) -> set[str]:
    return {str(topic) for _p, n, topic, _t in rows(analysis, "subscriber") if n == node}


def test_one_subscriber_per_element_the_launch_file_sets() -> None:
    analysis = analyse([SYSTEM], LAUNCH, {}, [])
    assert subscribed(analysis, "/rig/sync_saver") == {"/rig/left/image_raw", "/rig/right/image_raw"}
    published = {str(topic) for _p, n, topic, _t in rows(analysis, "publisher") if n == "/rig/stereo_sim"}
    assert published == {"/rig/left/image_raw", "/rig/right/image_raw", "/rig/left/camera_info",
                         "/rig/right/camera_info", "/rig/heartbeat"}  # get_namespace() is "/rig/"
    assert [d for d in analysis.diagnostics.items if d.code == "port-name-unknown"] == []


def test_a_list_parameter_left_unset_is_one_unknown_port_with_a_note(tmp_path: Path) -> None:
    shutil.copytree(SYSTEM, tmp_path / "ws")
    launch = tmp_path / "ws" / "src" / "stereo_saver" / "launch" / "rig.launch"
    launch.write_text(launch.read_text().replace('<rosparam param="inputs">[left/image_raw, right/image_raw]'
                                                 '</rosparam>', ""))
    analysis = analyse([tmp_path / "ws"], LAUNCH, {}, [])
    [name] = [topic for _p, n, topic, _t in rows(analysis, "subscriber") if n == "/rig/sync_saver"]
    assert isinstance(name, Unknown) and name.expr == "each element of ~inputs (not set by the configuration)"
    [note] = [d for d in analysis.diagnostics.items if d.code == "port-name-unknown"]
    assert (note.file, note.line, note.severity) == ("src/stereo_saver/scripts/sync_saver.py", 16, "note")
    assert "each element of ~inputs" in note.message


def test_an_unknown_sequence_keeps_the_known_suffix(tmp_path: Path) -> None:
    script = tmp_path / "relay.py"
    script.write_text("import sys\nimport rospy\nfrom std_msgs.msg import String\nrospy.init_node('relay')\n"
                      "for name in sys.argv[1:]:\n    rospy.Subscriber(name + '/in', String, print)\n")
    [port] = extract_python(script, "p", "relay.py", "relay.py", DiagnosticSink()).ports
    assert isinstance(port.name, Concat)
    head, tail = port.name.parts
    assert isinstance(head, Unknown) and head.expr == "an element of sys.argv[1:] (a sequence not known statically)"
    assert tail == "/in"


def test_a_loop_past_the_steps_budget_is_read_once(tmp_path: Path) -> None:
    script = tmp_path / "many.py"
    topics = ", ".join(f"'t{i}'" for i in range(50))
    script.write_text(f"import rospy\nfrom std_msgs.msg import String\nrospy.init_node('many')\n"
                      f"for t in [{topics}]:\n    rospy.Publisher(t, String, queue_size=1)\n")
    sink = DiagnosticSink()
    with budget.active({"steps": 100}):
        ports = extract_python(script, "p", "many.py", "many.py", sink).ports
    assert [p.name for p in ports if not isinstance(p.name, Unknown)] == []
    assert len(ports) == 1
    [warning] = sink.items
    assert (warning.code, warning.line, warning.severity) == ("budget-exceeded", 4, "warning")
    with budget.active({}):
        assert len(extract_python(script, "p", "many.py", "many.py", DiagnosticSink()).ports) == 50


def test_a_list_parameters_element_names_ports_only(tmp_path: Path) -> None:
    """A list parameter's element expands a port's name per element; as a type or a parameter's
    default it is unknown (nothing expands those)."""
    script = tmp_path / "typed.py"
    script.write_text("import rospy\nrospy.init_node('typed')\nfor t in rospy.get_param('~types'):\n"
                      "    rospy.Publisher('out', t, queue_size=1)\n    rospy.get_param('~x', t)\n")
    ports = extract_python(script, "p", "typed.py", "typed.py", DiagnosticSink()).ports
    [publisher] = [p for p in ports if p.kind == "publisher"]
    [read] = [p for p in ports if p.kind == "param_read" and p.name == "~x"]
    assert isinstance(publisher.type, Unknown)
    assert isinstance(read.default, Unknown) and read.default.expr == "an element of list parameter ~types"


def test_a_list_parameters_default_and_its_elements_fields(tmp_path: Path) -> None:
    """Unset, a list parameter is its default list; a list of dicts names ports by a field."""
    package = tmp_path / "src" / "muxer"
    (package / "scripts").mkdir(parents=True)
    (package / "launch").mkdir()
    (package / "package.xml").write_text("<package format='2'><name>muxer</name><version>0.1.0</version>"
                                         "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
                                         "<license>BSD</license><buildtool_depend>catkin</buildtool_depend></package>")
    (package / "CMakeLists.txt").write_text("cmake_minimum_required(VERSION 3.0.2)\nproject(muxer)\n"
                                            "find_package(catkin REQUIRED)\ncatkin_package()\n")
    script = package / "scripts" / "muxer.py"
    script.write_text("#!/usr/bin/env python3\nimport rospy\nfrom std_msgs.msg import String\n"
                      "rospy.init_node('muxer')\n"
                      "for name in rospy.get_param('~outputs', ['out_a', 'out_b']):\n"
                      "    rospy.Publisher(name, String, queue_size=1)\n"
                      "for source in rospy.get_param('~sources'):\n"
                      "    rospy.Subscriber(source['topic'], String, print)\n")
    script.chmod(0o755)
    (package / "launch" / "mux.launch").write_text(
        "<launch><node pkg='muxer' type='muxer.py' name='muxer'><rosparam param='sources'>"
        "[{name: joy, topic: joy_cmd}, {name: nav, topic: /nav_cmd}]</rosparam></node></launch>")
    analysis = analyse([tmp_path], ["muxer/launch/mux.launch"], {}, [])
    assert subscribed(analysis, "/muxer") == {"/joy_cmd", "/nav_cmd"}
    assert {str(t) for _p, n, t, _ty in rows(analysis, "publisher") if n == "/muxer"} == {"/out_a", "/out_b"}


def test_get_namespace_at_the_root_is_a_slash(tmp_path: Path) -> None:
    shutil.copytree(SYSTEM, tmp_path / "ws")
    launch = tmp_path / "ws" / "src" / "stereo_saver" / "launch" / "rig.launch"
    launch.write_text(launch.read_text().replace('<group ns="rig">', "").replace("</group>", ""))
    analysis = analyse([tmp_path / "ws"], LAUNCH, {}, [])
    assert "/heartbeat" in {str(t) for _p, n, t, _ty in rows(analysis, "publisher") if n == "/stereo_sim"}
