"""Ports listed in a YAML file a node's parameter names (yocs_cmd_vel_mux's yaml_cfg_file):
system/param_files.py, with the shipped model archlog/models/yocs_cmd_vel_mux.yaml."""

from __future__ import annotations

from pathlib import Path

from archlog.analysis import analyse
from archlog.values import Unknown

MUX_YAML = """subscribers:
  - name: "Teleoperation"
    topic: "input/teleop"
    priority: 7
  - name: "Navigation"
    topic: "/nav_cmd_vel"
    priority: 5
publisher: "out/cmd_vel"
"""


def _analyse(tmp_path: Path, params: str, files: dict[str, str] | None = None):
    for name, text in (files or {}).items():
        (tmp_path / name).write_text(text)
    launch = tmp_path / "mux.launch"
    launch.write_text(f"""<launch>
  <node pkg="nodelet" type="nodelet" name="manager" args="manager"/>
  <node pkg="nodelet" type="nodelet" name="cmd_vel_mux" args="load yocs_cmd_vel_mux/CmdVelMuxNodelet manager">
    {params}
    <remap from="cmd_vel_mux/out/cmd_vel" to="base/cmd_vel"/>
  </node>
</launch>""")
    return analyse([tmp_path], [str(launch)], {}, [])


def _ports(analysis, relation: str) -> list[tuple[str, object]]:
    return sorted(((t if isinstance(t, str) else "?", ty) for _p, n, t, ty in analysis.store.rows(relation)
                   if n == "/cmd_vel_mux" and t != "/manager/bond"), key=str)


def test_the_file_lists_the_mux_inputs_and_its_output(tmp_path: Path) -> None:
    analysis = _analyse(tmp_path, '<param name="yaml_cfg_file" value="$(dirname)/mux.yaml"/>', {"mux.yaml": MUX_YAML})
    assert _ports(analysis, "subscriber") == [("/cmd_vel_mux/input/teleop", "geometry_msgs/Twist"),
                                              ("/nav_cmd_vel", "geometry_msgs/Twist")]
    assert ("/base/cmd_vel", "geometry_msgs/Twist") in _ports(analysis, "publisher")  # remapped
    teleop = next(p for p, n, t, _ty in analysis.store.rows("subscriber") if t == "/cmd_vel_mux/input/teleop")
    assert analysis.store.location(teleop)[:2] == ("mux.yaml", 2)  # the entry's line in the file
    assert analysis.diagnostics.items == []


def test_without_a_publisher_entry_the_output_is_the_default(tmp_path: Path) -> None:
    analysis = _analyse(tmp_path, '<param name="yaml_cfg_file" value="$(dirname)/mux.yaml"/>',
                        {"mux.yaml": "subscribers:\n  - {name: a, topic: input/a}\n"})
    assert [t for t, _ty in _ports(analysis, "publisher")] == [
        "/cmd_vel_mux/active", "/cmd_vel_mux/output", "/cmd_vel_mux/parameter_descriptions",
        "/cmd_vel_mux/parameter_updates"]


def test_a_missing_file_is_reported_at_the_parameter(tmp_path: Path) -> None:
    analysis = _analyse(tmp_path, '<param name="yaml_cfg_file" value="$(dirname)/absent.yaml"/>')
    [diag] = [d for d in analysis.diagnostics.items if d.code == "not-a-file"]
    assert (diag.file, diag.line) == ("mux.launch", 4) and "yaml_cfg_file" in diag.message
    assert [t for t, _ty in _ports(analysis, "subscriber")] == ["?"]


def test_a_file_outside_the_workspace_is_not_read(tmp_path: Path) -> None:
    outside = tmp_path / "outside.yaml"
    outside.write_text(MUX_YAML)
    workspace = tmp_path / "ws"
    workspace.mkdir()
    analysis = _analyse(workspace, f'<param name="yaml_cfg_file" value="{outside}"/>')
    [diag] = [d for d in analysis.diagnostics.items if d.code == "outside-workspace"]
    assert (diag.file, diag.line) == ("mux.launch", 4)
    assert [t for t, _ty in _ports(analysis, "subscriber")] == ["?"]


def test_an_unset_parameter_leaves_the_names_unknown(tmp_path: Path) -> None:
    analysis = _analyse(tmp_path, "")
    [name] = [t for _p, n, t, _ty in analysis.store.rows("subscriber") if n == "/cmd_vel_mux" and t != "/manager/bond"]
    assert isinstance(name, Unknown) and "not set by the configuration" in name.expr
    assert sorted(d.code for d in analysis.diagnostics.items) == ["port-name-unknown"] * 2  # the input and the output


def test_bad_entries_are_diagnostics_at_their_line(tmp_path: Path) -> None:
    bad = "subscribers:\n  - {name: a, topic: input/a}\n  - {name: b, priority: 3}\n  - just_a_word\n"
    analysis = _analyse(tmp_path, '<param name="yaml_cfg_file" value="$(dirname)/mux.yaml"/>', {"mux.yaml": bad})
    assert [t for t, _ty in _ports(analysis, "subscriber")] == ["/cmd_vel_mux/input/a"]
    problems = sorted((d.file, d.line, d.code) for d in analysis.diagnostics.items)
    assert problems == [("mux.yaml", 3, "ports-file"), ("mux.yaml", 4, "ports-file")]


def test_invalid_yaml_a_relative_path_and_a_file_without_inputs(tmp_path: Path) -> None:
    unknown = ["port-name-unknown", "port-name-unknown", "ports-file"]  # the inputs and the output are unknown
    for value, text, codes in (("$(dirname)/mux.yaml", "subscribers: [unclosed\n", unknown),
                               ("mux.yaml", MUX_YAML, unknown),
                               ("$(dirname)/mux.yaml", "publisher: out\n", ["ports-file"])):
        analysis = _analyse(tmp_path, f'<param name="yaml_cfg_file" value="{value}"/>', {"mux.yaml": text})
        assert sorted(d.code for d in analysis.diagnostics.items) == codes, value
        assert all(d.line > 0 for d in analysis.diagnostics.items)


def test_ports_a_model_lists_by_parameter_count_when_a_source_resolves_fewer(tmp_path: Path) -> None:
    """A source whose inputs come from a list parameter it reads in a way archlog cannot follow
    resolves fewer ports than the model that names that list: the model is used."""
    pkg = tmp_path / "twist_mux"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "package.xml").write_text("<package format='2'><name>twist_mux</name><version>0.1.0</version>"
                                     "<description>d</description><maintainer email='m@example.com'>m</maintainer>"
                                     "<license>MIT</license></package>")
    (pkg / "scripts" / "twist_mux").write_text("""#!/usr/bin/env python3
import rospy
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import Twist
rospy.init_node('twist_mux')
rospy.Publisher('cmd_vel_out', Twist, queue_size=1)
rospy.Publisher('/diagnostics', DiagnosticArray, queue_size=1)
for entry in rospy.get_param('~topics'):
    rospy.Subscriber(entry['topic'], Twist, print)
""")
    (pkg / "scripts" / "twist_mux").chmod(0o755)
    launch = tmp_path / "mux.launch"
    launch.write_text("""<launch><node pkg="twist_mux" type="twist_mux" name="twist_mux">
  <rosparam>topics: [{name: joy, topic: joy_vel, timeout: 0.5, priority: 10}]</rosparam>
</node></launch>""")
    analysis = analyse([tmp_path], [str(launch)], {}, [])
    assert sorted(t for _p, n, t, _ty in analysis.store.rows("subscriber") if isinstance(t, str)) == ["/joy_vel"]
