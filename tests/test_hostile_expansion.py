"""Hostile expansions in launch files and parameter files: each bomb finishes within the harness's
time and memory limits, without a traceback, with a `budget-exceeded` (or include-cycle)
diagnostic at the file:line that crossed the limit.

Cases are grouped by what they exercise; each group is one workspace and one `archlog check` run
(every launch file given is its own unit of the budget), and each case asserts its own diagnostic.
"""

from __future__ import annotations

import json
import textwrap
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest
from support.hostile import Outside, Run, problems, run_check

from archlog import budget
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.ros1 import LaunchInterpreter
from archlog.extract.workspace.index import Workspace

PACKAGE_XML = """<package format="2"><name>demo</name><version>0.0.0</version><description>demo</description>
<maintainer email="demo@example.com">demo</maintainer><license>MIT</license></package>
"""
LAUNCH = "demo/launch"


@dataclass(frozen=True)
class Case:
    """A hostile launch file (with the files it needs), launched by itself, and where it must be stopped:
    `file`, a `line` or a set of lines where the crossing may be, and the diagnostic `code` (None:
    nothing to report, the run must only finish)."""

    name: str
    group: str
    files: dict[str, str]
    launch: str
    file: str
    lines: frozenset[int]
    code: str | None = "budget-exceeded"


def case(name: str, group: str, files: dict[str, str], launch: str, file: str | None = None,
         line: int | Callable[[], frozenset[int]] = 1, code: str | None = "budget-exceeded") -> Case:
    """Files are named in the launch folder, or from the workspace root when they start with demo/."""
    lines = frozenset([line]) if isinstance(line, int) else line()
    paths = {k if k.startswith("demo/") else f"{LAUNCH}/{k}": textwrap.dedent(v).lstrip() for k, v in files.items()}
    return Case(name, group, paths, f"{LAUNCH}/{launch}", f"{LAUNCH}/{file or launch}", lines, code)


def ros1(body: str) -> str:
    return f"<launch>\n{body}</launch>\n"


def ros1_eval(name: str, expr: str) -> Case:
    """A ROS 1 <param> whose value is `$(eval expr)`, on line 2."""
    return case(name, "ros1", {f"{name}.launch": ros1(f'  <param name="p" value="$(eval {expr})"/>\n')},
                f"{name}.launch", line=2)


def doubling(tag: str, ref: str, count: int = 39) -> str:
    """`count` args (or lets) each twice the one before: 2**count characters unless stopped."""
    lines = [f'  <{tag} name="a0" value="x"/>\n']
    lines += [f'  <{tag} name="a{i}" value="{ref.format(i - 1)}{ref.format(i - 1)}"/>\n' for i in range(1, count + 1)]
    return "".join(lines)


def doubling_line() -> frozenset[int]:
    """The line of the arg whose value no longer fits: arg i (on line i + 2) brings 2**i characters."""
    spent, i = 0, 0
    while spent <= budget.LIMITS["characters"]:
        i += 1
        spent += 2 ** i
    return frozenset([i + 2])


def laughs(indent: str, count: int = 30) -> str:
    """YAML anchors each a list of the one before twice: 2**count elements when expanded."""
    lines = [f"{indent}a0: &a0 [lol, lol]"] + [f"{indent}a{i}: &a{i} [*a{i - 1}, *a{i - 1}]" for i in range(1, count)]
    return "\n".join(lines) + "\n"


def python(body: str) -> str:
    return ("from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
            "def generate_launch_description():\n" + textwrap.indent(textwrap.dedent(body).lstrip(), "    "))


def python_value(name: str, expr: str, group: str = "python") -> Case:
    """A Python launch file computing `expr` on line 6 (then still launching a node)."""
    return case(name, group, {f"{name}.launch.py": python(f"""
        value = {expr}
        return LaunchDescription([Node(package='demo', executable='x', name='{name}')])
        """)}, f"{name}.launch.py", line=6)


def alternatives_script() -> str:
    """A rospy node whose topic is an f-string of 8 names, each one of 16 values: 16**8 combinations."""
    lines = ["#!/usr/bin/env python", "import sys", "import rospy", "from std_msgs.msg import String", ""]
    for name in "abcdefgh":
        lines += [f"{name} = '{name}'"] + [f"if len(sys.argv) == {i}:\n    {name} = '{name}{i}'" for i in range(15)]
    lines += ["rospy.init_node('talker')", "rospy.Publisher(f'{a}{b}{c}{d}{e}{f}{g}{h}', String, queue_size=1)"]
    return "\n".join(lines) + "\n"


FAN = {f"fan{i}.launch": ros1(f'  <include file="$(find demo)/launch/fan{i + 1}.launch"/>\n' * 2) for i in range(30)}
FAN["fan30.launch"] = ros1("".join(f'  <arg name="a{i}" default="1"/>\n' for i in range(1000)))  # args, not nodes:
# 2**30 node instances would be a bomb for the rules, not for the launch reader

CASES = [
    case("self_include", "ros1", {"self.launch": ros1('  <include file="$(find demo)/launch/self.launch"/>\n' * 2)},
         "self.launch", line=2, code="launch-include-cycle"),
    case("cycle_through", "ros1", {"ping.launch": ros1('  <include file="$(find demo)/launch/pong.launch"/>\n'),
                                   "pong.launch": ros1('  <include file="$(find demo)/launch/ping.launch"/>\n')},
         "ping.launch", "pong.launch", line=2, code="launch-include-cycle"),
    case("fan_out", "fan", FAN, "fan0.launch", "fan30.launch", line=lambda: frozenset(range(2, 1002))),
    case("arg_doubling", "ros1", {"args.launch": ros1(doubling("arg", "$(arg a{})"))}, "args.launch", line=doubling_line),
    case("rosparam_laughs", "ros1", {"laughs.launch": ros1("  <rosparam>\n" + laughs("    ").replace("&", "&amp;")
                                                           + "  </rosparam>\n")},
         "laughs.launch", line=2),
    case("rosparam_deep", "ros1", {"deep.launch": ros1("  <rosparam>\n    a: " + "[" * 5000 + "]" * 5000
                                                       + "\n  </rosparam>\n")}, "deep.launch", line=2),
    case("rviz_laughs", "ros1", {"rviz.launch": ros1('  <node pkg="rviz" type="rviz" name="rviz" '
                                                     'args="-d $(find demo)/launch/laughs.rviz"/>\n'),
                                 "laughs.rviz": laughs("")}, "rviz.launch", line=2),
    case("ports_file_laughs", "ros1", {"mux.launch": ros1(
        '  <node pkg="nodelet" type="nodelet" name="mux" args="load yocs_cmd_vel_mux/CmdVelMuxNodelet m">\n'
        '    <param name="yaml_cfg_file" value="$(find demo)/launch/mux_laughs.yaml"/>\n  </node>\n'),
        "mux_laughs.yaml": "subscribers:\n" + laughs("  ")}, "mux.launch", line=3),
    ros1_eval("eval_power_tower", "9**9**9**9"),
    ros1_eval("eval_factorial", "factorial(10**8)"),
    ros1_eval("eval_exponent_past_floats", "2**(10**400)"),
    ros1_eval("eval_percent_width", "'%99999999d' % 1"),
    ros1_eval("eval_fstring_width", "f'{1:>99999999}'"),
    ros1_eval("eval_format_width", "'{:>99999999}'.format(1)"),
    ros1_eval("eval_string_bomb", "'a' * 10**10"),
    ros1_eval("eval_round", "round(5, -10**9)"),
    ros1_eval("eval_nested", "-" * 100_000 + "1"),
    case("eval_func_globals", "ros1", {"globals.launch": ros1(
        '  <param name="p" value="$(eval \'{0.func_globals}\'.format(arg))"/>\n')}, "globals.launch", line=2,
         code="launch-subst"),
    case("fstring_alternatives", "ros1", {"demo/scripts/talker.py": alternatives_script(),
                                          "talker.launch": ros1('  <node pkg="demo" type="talker.py" name="t"/>\n')},
         "talker.launch", code=None),
    case("xml_self_include", "ros2", {"self.launch.xml": """
        <launch>
          <let name="x" value="1"/>
          <include file="$(dirname)/self.launch.xml"/>
        </launch>
        """}, "self.launch.xml", line=3, code="launch-include-cycle"),
    case("let_doubling", "ros2", {"lets.launch.xml": "<launch>\n" + doubling("let", "$(var a{})") + "</launch>\n"},
         "lets.launch.xml", line=doubling_line),
    case("yaml_launch_laughs", "ros2", {"laughs.launch.yaml": "launch:\n- let: {name: x, value: '1'}\nbombs:\n"
                                        + laughs("  ")}, "laughs.launch.yaml", line=lambda: frozenset(range(4, 34))),
    case("yaml_launch_deep", "ros2", {"deep.launch.yaml": "launch: " + "[" * 5000 + "]" * 5000 + "\n"},
         "deep.launch.yaml", line=1),
    case("params_laughs", "ros2", {"params.launch.xml": """
        <launch>
          <node pkg="demo" exec="x" name="talker"><param from="$(dirname)/laughs.yaml"/></node>
        </launch>
        """, "laughs.yaml": "talker:\n  ros__parameters:\n" + laughs("    ")}, "params.launch.xml", "laughs.yaml",
         line=lambda: frozenset(range(4, 33))),
    case("params_deep", "ros2", {"deep_params.launch.xml": """
        <launch>
          <node pkg="demo" exec="x" name="talker"><param from="$(dirname)/deep.yaml"/></node>
        </launch>
        """, "deep.yaml": "talker:\n  ros__parameters:\n    a: " + "[" * 5000 + "]" * 5000 + "\n"},
         "deep_params.launch.xml", "deep.yaml", line=3),
    python_value("py_string_bomb", "'a' * 10**10"),
    python_value("py_power_tower", "9**9**9**9"),
    python_value("py_percent_width", "'%99999999d' % 1"),
    python_value("py_fstring_width", "f'{1:>99999999}'"),
    python_value("py_format_width", "'{:>99999999}'.format(1)"),
    python_value("py_comprehension", "[0 for a in range(9999) for b in range(9999)]", "steps"),
    python_value("py_doubling_list", "sum([[0] * 10_000] * 10_000, [])"),
    python_value("py_text_of_shared_list", "str([[0] * 10_000] * 10_000)"),
    case("py_recursive_lambda", "recursion", {"lambda.launch.py": python("""
        f = lambda n: [f(n), f(n), f(n), f(n)]
        value = f(0)
        return LaunchDescription([])
        """)}, "lambda.launch.py", line=7),
    case("py_deep_source", "python", {"deep.launch.py": "X = " + "-" * 100_000 + "1\n"}, "deep.launch.py", line=1),
    python_value("py_deep_tree", "(1 + " * 150 + "1" + ")" * 150),
    case("py_include_cycle", "python", {"cycle.launch.py": python("""
        from launch.actions import IncludeLaunchDescription
        from launch.launch_description_sources import PythonLaunchDescriptionSource
        return LaunchDescription([IncludeLaunchDescription(PythonLaunchDescriptionSource(__file__))])
        """)}, "cycle.launch.py", line=8, code="launch-include-cycle"),
    case("py_yaml_laughs", "python", {"yaml.launch.py": python("""
        import os
        import yaml
        with open(os.path.join(os.path.dirname(__file__), 'laughs.yaml')) as f:
            value = yaml.safe_load(f)
        return LaunchDescription([])
        """), "laughs.yaml": laughs("")}, "yaml.launch.py", line=9),
]


@pytest.fixture(scope="module")
def runs(tmp_path_factory: pytest.TempPathFactory) -> Callable[[str], tuple[Run, Outside, list[dict]]]:
    """One `archlog check` per group (run when a case of it first asks), with its diagnostics."""
    done: dict[str, tuple[Run, Outside, list[dict]]] = {}

    def run(group: str) -> tuple[Run, Outside, list[dict]]:
        if group not in done:
            root = tmp_path_factory.mktemp(group)
            workspace, outside = root / "ws", Outside(root / "outside")
            (workspace / "demo").mkdir(parents=True)
            (workspace / "demo" / "package.xml").write_text(PACKAGE_XML)
            launches = []
            for c in CASES:
                if c.group == group:
                    for path, text in c.files.items():
                        (workspace / path).parent.mkdir(parents=True, exist_ok=True)
                        (workspace / path).write_text(text)
                        if text.startswith("#!"):
                            (workspace / path).chmod(0o755)
                    launches += ["--launch", c.launch]
            result = run_check(workspace, outside, *launches, fmt="json")
            try:
                diagnostics = json.loads(result.output[result.output.index("{"):])["diagnostics"]
            except ValueError:
                diagnostics = []
            done[group] = (result, outside, diagnostics)
        return done[group]

    return run


@pytest.mark.parametrize("hostile", CASES, ids=lambda c: c.name)
def test_expansion_is_stopped_where_it_crosses_the_budget(hostile: Case, runs: Callable) -> None:
    run, outside, diagnostics = runs(hostile.group)
    assert problems(run, outside) == []
    if hostile.code is None:
        return
    found = {(d["file"], d["line"]) for d in diagnostics if d["code"] == hostile.code}
    assert any((hostile.file, line) in found for line in hostile.lines), (hostile.code, sorted(found))


def test_a_raised_limit_lets_a_deeper_honest_include_chain_through(tmp_path: Path) -> None:
    """70 launch files each including the next: deeper than the default depth limit (64)."""
    (tmp_path / "demo").mkdir()
    (tmp_path / "demo" / "package.xml").write_text(PACKAGE_XML)
    for i in range(70):
        body = f'  <include file="$(dirname)/l{i + 1}.launch"/>\n' if i < 69 else '  <node pkg="demo" type="x" name="deep"/>\n'
        (tmp_path / "demo" / f"l{i}.launch").write_text(ros1(body))

    def nodes() -> tuple[list[str], list[str]]:
        sink = DiagnosticSink()
        config = LaunchInterpreter(Workspace([tmp_path], sink), sink).load([tmp_path / "demo" / "l0.launch"], {})
        return [n.name for n in config.nodes], [d.code for d in sink.items if d.code == "budget-exceeded"]

    assert nodes() == ([], ["budget-exceeded"])
    with budget.active({"depth": 128}):
        assert nodes() == (["/deep"], [])
