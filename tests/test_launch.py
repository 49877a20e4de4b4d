"""ROS 1 launch interpretation: args, groups, includes, remap scoping, params, conditions."""

from __future__ import annotations

from pathlib import Path

import pytest

from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch import conditions
from archlog.extract.launch.model import LaunchConfig, SubstitutionError
from archlog.extract.launch.ros1 import LaunchInterpreter
from archlog.extract.launch.ros1_subst import SubstContext, substitute
from archlog.extract.workspace.index import Workspace


def load(tmp_path: Path, files: dict[str, str], args: dict[str, str] | None = None) -> tuple[LaunchConfig, DiagnosticSink]:
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    sink = DiagnosticSink()
    config = LaunchInterpreter(Workspace([tmp_path], sink), sink).load([tmp_path / "main.launch"], args or {})
    return config, sink


def test_group_namespaces_and_remap_scoping(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.launch": """<launch>
  <node pkg="p" type="t" name="before"/>
  <remap from="scan" to="base_scan"/>
  <group ns="r1">
    <remap from="odom" to="odometry"/>
    <node pkg="p" type="t" name="a" ns="sub"><remap from="x" to="y"/></node>
  </group>
  <node pkg="p" type="t" name="after"/>
</launch>"""})
    nodes = {n.name: n for n in config.nodes}
    assert set(nodes) == {"/before", "/r1/sub/a", "/after"}
    assert [(a, b) for a, b, _ in nodes["/before"].remaps] == []
    assert [(a, b) for a, b, _ in nodes["/r1/sub/a"].remaps] == [("scan", "base_scan"), ("odom", "odometry"), ("x", "y")]
    assert [(a, b) for a, b, _ in nodes["/after"].remaps] == [("scan", "base_scan")]
    assert nodes["/r1/sub/a"].namespace == "/r1/sub"
    assert sink.items == []


def test_args_defaults_values_and_include(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {
        "main.launch": """<launch>
  <arg name="robot" default="r1"/>
  <include file="$(dirname)/child.launch" ns="$(arg robot)">
    <arg name="name" value="$(arg robot)_driver"/>
  </include>
</launch>""",
        "child.launch": """<launch>
  <arg name="name"/>
  <arg name="rate" default="10"/>
  <node pkg="p" type="t" name="$(arg name)"><param name="rate" value="$(arg rate)"/></node>
</launch>"""}, {"robot": "r7"})
    assert [n.name for n in config.nodes] == ["/r7/r7_driver"]
    assert config.params["/r7/r7_driver/rate"][0] == 10
    assert sink.items == []


def test_conditions_and_eval(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.launch": """<launch>
  <arg name="sim" default="true"/>
  <arg name="mode" default="fast"/>
  <node if="$(arg sim)" pkg="p" type="t" name="sim_only"/>
  <node unless="$(arg sim)" pkg="p" type="t" name="real_only"/>
  <node if="$(eval mode == 'fast' and sim)" pkg="p" type="t" name="fast"/>
  <node if="$(eval arg('mode').upper() == 'SLOW' or False)" pkg="p" type="t" name="slow"/>
</launch>"""})
    assert [n.name for n in config.nodes] == ["/sim_only", "/fast"]


def test_unresolvable_condition_keeps_element_as_conditional(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {"main.launch": """<launch>
  <node if="$(env ARCHLOG_TEST_SURELY_UNSET)" pkg="p" type="t" name="maybe"/>
</launch>"""})
    [node] = config.nodes
    assert node.name == "/maybe" and node.condition.startswith('if="$(env ARCHLOG_TEST_SURELY_UNSET)"')
    assert [(d.line, d.code) for d in sink.items] == [(2, "launch-condition"), (2, "env-not-given")]


def test_undecided_conditions_on_one_unknown_arg_are_tried_with_their_values(tmp_path: Path) -> None:
    config, _ = load(tmp_path, {"main.launch": """<launch>
  <arg name="model" default="$(env ARCHLOG_TEST_SURELY_UNSET)"/>
  <arg name="sim" default="$(env ARCHLOG_TEST_SURELY_UNSET)"/>
  <group if="$(eval model == 'a')">
    <node pkg="p" type="t" name="a"/>
    <node if="$(arg sim)" pkg="p" type="t" name="a_sim"/>
  </group>
  <node if="$(eval model in ('b', 'c'))" pkg="p" type="t" name="b_or_c"/>
  <node unless="$(arg sim)" pkg="p" type="t" name="real"/>
  <node if="$(eval model == sim)" pkg="p" type="t" name="both_args"/>
  <node if="$(env ARCHLOG_TEST_SURELY_UNSET)" pkg="p" type="t" name="no_arg"/>
</launch>"""})
    nodes = {n.name: n for n in config.nodes}
    assert nodes["/a"].when == {"model#1": frozenset({"a"})}
    # nested conditions are both kept, each on its own argument
    assert nodes["/a_sim"].when == {"model#1": frozenset({"a"}), "sim#2": frozenset({"true", "1"})}
    assert " and " in (nodes["/a_sim"].condition or "")
    assert nodes["/b_or_c"].when == {"model#1": frozenset({"b", "c"})}
    assert nodes["/real"].when == {"sim#2": frozenset({"false", "0"})}
    # a condition on two unknown arguments, or on no argument, is not tried
    assert nodes["/both_args"].when is None and nodes["/both_args"].condition
    assert nodes["/no_arg"].when is None and nodes["/no_arg"].condition


def test_condition_trials_have_a_budget(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(conditions, "_MAX_TRIALS", 20)
    nodes = "".join(f'<node if="$(eval model == \'m{i}\')" pkg="p" type="t" name="n{i}"/>' for i in range(3))
    config, _ = load(tmp_path, {"main.launch": f"""<launch>
  <arg name="model" default="$(env ARCHLOG_TEST_SURELY_UNSET)"/>{nodes}
</launch>"""})
    # each guard is tried with the 10 values the three conditions give (words, booleans) and one other: 11 each
    assert [n.when is not None for n in config.nodes] == [True, False, False]


def test_params_types_rosparam_and_node_args(tmp_path: Path) -> None:
    config, _ = load(tmp_path, {"main.launch": """<launch>
  <param name="global_int" value="3"/>
  <param name="as_str" value="3" type="str"/>
  <param name="flag" value="True"/>
  <param name="robot_description" command="xacro robot.urdf.xacro"/>
  <group ns="g">
    <rosparam>{speed: 1.5, pid: {p: 2, d: 0}}</rosparam>
    <node pkg="p" type="t" name="n" args="__name:=renamed in:=/input _rate:=5"/>
  </group>
</launch>"""})
    values = {k: v for k, (v, _e) in config.params.items()}
    assert values["/global_int"] == 3 and values["/as_str"] == "3" and values["/flag"] is True
    assert values["/g/speed"] == 1.5 and values["/g/pid/p"] == 2 and values["/g/pid/d"] == 0
    assert values["/g/renamed/rate"] == 5
    assert type(values["/robot_description"]).__name__ == "Unknown"
    node = config.nodes[0]
    assert node.name == "/g/renamed" and [(a, b) for a, b, _ in node.remaps] == [("in", "/input")]


def test_bad_launch_input_becomes_diagnostics(tmp_path: Path) -> None:
    config, sink = load(tmp_path, {
        "main.launch": """<launch>
  <include file="$(dirname)/missing.launch"/>
  <include file="$(dirname)/broken.launch"/>
  <node pkg="$(find no_such_package_xyz)" type="t" name="x"/>
  <node pkg="p" type="t" name="ok"/>
</launch>""",
        "broken.launch": "<launch>\n  <node pkg='p' type='t' name='n'\n</launch>\n"})
    assert [n.name for n in config.nodes] == ["/ok"]
    found = {(d.file, d.line, d.code) for d in sink.items}
    assert ("main.launch", 2, "launch-include") in found
    assert ("main.launch", 4, "launch-unresolved") in found
    # the skipped include and node are holes of the recovery, with a hint that can fix the cause
    assert [(file, line) for file, line, _why in config.holes] == [("main.launch", 2), ("main.launch", 4)]
    assert "add the folder of package no_such_package_xyz" in config.holes[1][2]
    assert any(f == "broken.launch" and code == "launch-xml" for f, _l, code in found)


@pytest.mark.parametrize("expr", [
    "__import__('os').system('touch /tmp/archlog_pwned')",
    "().__class__.__base__.__subclasses__()",
    "open('/etc/passwd').read()",
    "[x for x in range(3)]",
    "lambda: 1",
])
def test_eval_never_runs_arbitrary_code(expr: str) -> None:
    ctx = SubstContext({"a": "1"}, lambda _p: None, Path("/tmp/x.launch"))
    with pytest.raises(SubstitutionError):
        substitute(f"$(eval {expr})", ctx)
    assert not Path("/tmp/archlog_pwned").exists()


def test_substitution_nesting_and_optenv() -> None:
    ctx = SubstContext({"pkg": "demo", "n": "2"}, lambda p: Path(f"/ws/{p}"), Path("/ws/demo/launch/x.launch"),
                       env={"HOME": "/root"})
    assert substitute("$(find demo)/cfg $(arg pkg)", ctx) == "/ws/demo/cfg demo"
    with pytest.raises(SubstitutionError):
        substitute("$(find $(arg pkg))/cfg", ctx)  # roslaunch does not nest substitutions
    assert substitute("literal $(arg pkg", ctx) == "literal $(arg pkg"
    assert substitute("$(optenv NOPE fallback words)-$(env HOME)", ctx) == "fallback words-/root"
    assert substitute("$(eval int(n) * 2)", ctx) == "4"
    assert substitute("$(eval str(n) + 'x' + arg('pkg'))", ctx) == "2xdemo"
    assert substitute("$(dirname)", ctx) == "/ws/demo/launch"
    assert substitute("$(anon a)", ctx) == substitute("$(anon a)", ctx) != substitute("$(anon b)", ctx)


@pytest.mark.parametrize("body, nodes, diagnostics", [
    ('<node pkg="demo" type="talker" name="t"/>', ["/t"], []),
    ('<arg name="ns" default="x"/>\n<node pkg="demo" exec="talker" name="t" namespace="$(var ns)"/>', ["/x/t"], []),
    ('<let name="a" value="1"/>', [], []),
    ('<node pkg="demo" type="talker" name="$(var who)"/>', [], [(2, "launch-attr"), (2, "launch-invalid")]),
    ('<group><push-ros-namespace namespace="r"/></group>', [], []),
])
def test_dialect_is_decided_by_content_not_file_name(tmp_path: Path, body: str, nodes: list[str],
                                                     diagnostics: list[tuple[int, str]]) -> None:
    """A <launch> file with ROS 2's tags, `exec` or substitutions is read as ROS 2 (see test_launch_ros2.py)."""
    (tmp_path / "main.launch.xml").write_text(f"<launch>\n{body}\n</launch>\n")
    sink = DiagnosticSink()
    config = LaunchInterpreter(Workspace([tmp_path], sink), sink).load([tmp_path / "main.launch.xml"], {})
    assert [n.name for n in config.nodes] == nodes
    assert [(d.line, d.code) for d in sink.items] == diagnostics


def test_a_file_included_many_times_is_parsed_once_and_each_include_spends_the_budget(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from archlog import budget
    from archlog.extract.launch import ros1_scope

    parsed: list[Path] = []
    real = ros1_scope.open_xml
    monkeypatch.setattr(ros1_scope, "open_xml", lambda path, *rest: parsed.append(path) or real(path, *rest))
    unit = '<launch><arg name="ns"/><group ns="$(arg ns)"><node pkg="p" type="t" name="a"/>' \
           '<node pkg="p" type="t" name="b"/></group></launch>'
    main = "<launch>" + "".join(f'<include file="$(dirname)/unit.launch"><arg name="ns" value="r{i}"/></include>'
                                for i in range(5)) + "</launch>"
    config, sink = load(tmp_path, {"main.launch": main, "unit.launch": unit})
    assert sorted(n.name for n in config.nodes) == sorted(f"/r{i}/{n}" for i in range(5) for n in "ab")
    assert parsed.count(tmp_path / "unit.launch") == 1 and not sink.items
    with budget.active({"elements": 12}):  # each include spends 5: itself, the file's arg, group and nodes
        config, sink = load(tmp_path, {"main.launch": main, "unit.launch": unit})
    assert [n.name for n in config.nodes] == ["/r0/a", "/r0/b", "/r1/a", "/r1/b"]
    assert [d.code for d in sink.items] == ["budget-exceeded"]
