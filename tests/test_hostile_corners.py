"""Hostile corners (issue 15): inputs whose cost grows faster than their size (CMake tokens,
Python 2 repair, long names, large or macro-doubling C++) and inputs that are nested too deeply or
have the wrong types (Python, YAML of rviz configs, node models, parameter files). Each is a
diagnostic at file:line within time and memory, never a traceback.

Whole runs go through tests/support/hostile.py; the fixed functions are also timed directly, and
every reader is fed random bytes and random nested YAML/XML trees (hypothesis)."""

from __future__ import annotations

import json
import string
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from lxml import etree
from support.hostile import Outside, problems, run_check

from archlog import budget
from archlog.diagnostics import DiagnosticSink
from archlog.extract.cpp.clang_ast import line_finder
from archlog.extract.cpp.stubs import members
from archlog.extract.launch.model import Element, LaunchConfig, LaunchNode
from archlog.extract.launch.ros1 import LaunchInterpreter
from archlog.extract.launch.ros1_params import convert
from archlog.extract.launch.ros2_params import load_param_file
from archlog.extract.python.node import extract_python
from archlog.extract.python.repair import parse_tolerant
from archlog.extract.workspace.cmake import commands
from archlog.extract.workspace.index import Workspace
from archlog.facts.similarity import near_pairs, too_long
from archlog.system.configured import configured_ports
from archlog.system.node_models import load_models

PACKAGE_XML = ("<package format='2'><name>{}</name><version>0.1.0</version><description>d</description>"
               "<maintainer email='dev@example.com'>m</maintainer><license>MIT</license></package>")
LAUGHS = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n" + "".join(
    f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 10)}]\n" for i in range(1, 10))  # 10^10 elements through aliases
TALKER = ("import rospy\nfrom std_msgs.msg import String\nrospy.init_node('talker')\n"
          "rospy.Publisher('chatter', String)\n")


# -- direct: the fixed functions, timed ---------------------------------------------------------
def test_cmake_of_3mb_short_tokens_is_linear() -> None:
    text = "set(A " + " x" * 1_000_000 + ")\n" + "f(a)\n" * 100_000
    begin = time.monotonic()
    found = commands(text)
    assert time.monotonic() - begin < 10 and len(found) == 100_001 and found[-1].line == 100_001


def test_cmake_growing_lists_stop_at_the_budget_with_the_line() -> None:
    stopped: list[tuple[int, str]] = []
    begin = time.monotonic()
    found = commands("cmake_minimum_required(VERSION 3.5)\n" + "list(APPEND X item)\n" * 40_000,
                     None, lambda line, message: stopped.append((line, message)))
    assert time.monotonic() - begin < 5
    assert len(stopped) == 1 and 1 < stopped[0][0] < 40_000 and "characters" in stopped[0][1]
    assert len(found) == stopped[0][0] - 1  # the commands before the line that crossed it are kept


def test_cmake_self_reference_of_an_unset_variable_is_nothing() -> None:
    variables: dict[str, str] = {}
    commands("set(SRCS ${SRCS} a.cpp)\n" * 30 + "set(B ${SRCS})\n", variables)
    assert variables["SRCS"].split(";") == ["a.cpp"] * 30  # no ${SRCS} left to grow 5x a line


@pytest.mark.parametrize("line", ["print x" + " " * 60_000 + "y", "raise E ," + " " * 60_000 + "y" + " " * 60_000 + "z",
                                  "exec x" + " \t" * 30_000 + "y"])
def test_python2_repair_of_a_long_blank_run_is_fast(line: str) -> None:
    begin = time.monotonic()
    tree, repaired, _dropped = parse_tolerant("import rospy\n" + line + "\n")
    assert time.monotonic() - begin < 2 and tree is not None and repaired == [2]


def test_python2_repair_of_20k_lines_is_capped(tmp_path: Path) -> None:
    path = tmp_path / "node.py"
    path.write_text("import rospy\n" + "print 'x'\nx = 1\ny = 2\nz = 3\n" * 5_000)
    sink = DiagnosticSink()
    begin = time.monotonic()
    summary = extract_python(path, "p", "node.py", "node.py", sink)
    assert time.monotonic() - begin < 5 and summary.incomplete
    assert [(d.line, d.code) for d in sink.items] == [(1, "python-syntax")] and "repair cap" in sink.items[0].message


@pytest.mark.parametrize(("source", "line"), [
    ("x = " + "(" * 100_000 + ")" * 100_000, 2), ("x = " + "[" * 100_000 + "]" * 100_000, 2),
    ("x = " + "-" * 100_000 + "1", 1), ("x = " + "+".join(["1"] * 100_000), 1), ("x = a" + ".b" * 100_000, 1),
    ("x = " + "+".join(["1"] * 900) + "\nrospy.Publisher(x, String)", 1),
])
def test_python_nested_too_deeply_is_a_diagnostic(tmp_path: Path, source: str, line: int) -> None:
    path = tmp_path / "deep.py"
    path.write_text("import rospy\n" + source + "\n")
    sink = DiagnosticSink()
    summary = extract_python(path, "p", "deep.py", "deep.py", sink)
    assert [(d.line, d.code) for d in sink.items] == [(line, "python-nesting")] and summary.incomplete


@settings(max_examples=50, deadline=None, database=None)
@given(st.text(alphabet="ab\n", max_size=200), st.integers(0, 200))
def test_line_finder_counts_newlines_before_the_offset(text: str, offset: int) -> None:
    assert line_finder(text)(offset) == text.count("\n", 0, offset) + 1


def test_names_of_20k_segments_are_not_compared() -> None:
    long = "/" + "/".join(f"s{i}" for i in range(20_000))
    begin = time.monotonic()
    pairs = near_pairs([long, long + "x", "/base_waypoint", "/base_waypoints"])
    assert time.monotonic() - begin < 2
    assert [(a, b) for a, b, _ in pairs] == [("/base_waypoint", "/base_waypoints")]
    assert "characters" in (too_long(long) or "") and "101 segments" in (too_long("/a" * 100) or "")
    assert too_long("/a/b") is None


# -- whole runs -------------------------------------------------------------------------------
def _package(root: Path, name: str, cmake: str = "", ros2: bool = False) -> Path:
    pkg = root / "src" / name
    pkg.mkdir(parents=True)
    (pkg / "package.xml").write_text(PACKAGE_XML.format(name).replace(
        "</package>", "<export><build_type>ament_cmake</build_type></export></package>" if ros2 else "</package>"))
    (pkg / "CMakeLists.txt").write_text(cmake or f"cmake_minimum_required(VERSION 3.5)\nproject({name})\n")
    return pkg


def _node(pkg: Path, name: str, source: str) -> None:
    (pkg / "scripts").mkdir(exist_ok=True)
    (pkg / "scripts" / name).write_text("#!/usr/bin/env python\n" + source)
    (pkg / "scripts" / name).chmod(0o755)


def _launch(root: Path, body: str) -> None:
    (root / "src" / "demo" / "launch").mkdir(parents=True, exist_ok=True)
    (root / "src" / "demo" / "launch" / "main.launch").write_text(f"<launch>\n{body}\n</launch>\n")


def case_cmake_tokens(root: Path) -> list[tuple[str, str]]:
    _package(root, "demo", "cmake_minimum_required(VERSION 3.5)\nproject(demo)\n" + "a(b c)\n" * 200_000
             + "list(APPEND X item)\n" * 30_000)
    return [("demo/CMakeLists.txt", "budget-exceeded")]


def case_python_repair(root: Path) -> list[tuple[str, str]]:
    pkg = _package(root, "demo")
    _node(pkg, "blanks.py", TALKER + "print x" + " " * 60_000 + "y\n")
    _node(pkg, "broken.py", "import rospy\n" + "print 'x'\nx = 1\ny = 2\nz = 3\n" * 5_000)
    _node(pkg, "parens.py", "import rospy\nx = " + "(" * 100_000 + ")" * 100_000 + "\n")
    _node(pkg, "unary.py", "import rospy\nx = " + "-" * 100_000 + "1\n")
    _node(pkg, "big.py", "import rospy\n" + "x = 1\n" * 300_000)
    return [("blanks.py", "python2"), ("broken.py", "python-syntax"), ("parens.py", "python-nesting"),
            ("unary.py", "python-nesting"), ("big.py", "too-large")]


def case_long_names(root: Path) -> list[tuple[str, str]]:
    pkg = _package(root, "demo")
    long = "/" + "/".join(f"s{i}" for i in range(20_000))
    _node(pkg, "talker.py", TALKER.replace("'chatter'", repr(long)) + f"rospy.Subscriber({long + 'x'!r}, String)\n")
    return [("talker.py", "name-too-long")]


def case_cpp(root: Path) -> list[tuple[str, str]]:
    macros = "".join(f"#define A{i} A{i - 1} A{i - 1}\n" for i in range(1, 41))
    pkg = _package(root, "demo", "cmake_minimum_required(VERSION 3.5)\nproject(demo)\n"
                   "add_executable(doubling src/doubling.cpp)\nadd_executable(big src/big.cpp)\n"
                   "add_executable(fallback src/fallback.cpp)\nadd_executable(copies src/copies.cpp)\n"
                   "add_executable(unused src/unused.cpp)\n")  # a macro not using its parameter: no crash
    (pkg / "src").mkdir()
    (pkg / "src" / "doubling.cpp").write_text(f"#include <ros/ros.h>\n#define A0 x\n{macros}"
                                              "int f() { return A40; }\n")
    (pkg / "src" / "big.cpp").write_text("#include <ros/ros.h>\n" + "int f(int a) { return a; }\n" * 300_000)
    calls = "".join(f'nh.advertise<std_msgs::String>("t", &C::cb{i}\n' for i in range(11_000))  # no ';' anywhere
    (pkg / "src" / "fallback.cpp").write_text("#include <ros/ros.h>\nvoid f() { ros::NodeHandle nh; undeclared();\n"
                                              + calls)
    (pkg / "src" / "copies.cpp").write_text("#include <ros/ros.h>\n#define F(x) x x\nint f() { return "
                                            + "F(" * 40 + "1" + ")" * 40 + "; }\n")
    (pkg / "src" / "unused.cpp").write_text("#include <ros/ros.h>\n#define G(x) 1\nint g() { return G(G(2)); }\n")
    return [("doubling.cpp", "cpp-macro"), ("big.cpp", "too-large"), ("fallback.cpp", "cpp-compile"),
            ("copies.cpp", "cpp-macro")]


def case_cpp_ros2_fallback(root: Path) -> list[tuple[str, str]]:
    pkg = _package(root, "demo", "cmake_minimum_required(VERSION 3.5)\nproject(demo)\n"
                   "add_executable(fallback src/fallback.cpp)\n", ros2=True)
    (pkg / "src").mkdir()
    calls = 'node->create_publisher<std_msgs::msg::String>("t", rclcpp::QoS(10\n' * 7_000  # never closed
    (pkg / "src" / "fallback.cpp").write_text("#include <rclcpp/rclcpp.hpp>\n#include <std_msgs/msg/string.hpp>\n"
                                              "void f(rclcpp::Node::SharedPtr node) { undeclared();\n" + calls)
    return [("fallback.cpp", "cpp-compile")]


def case_deep_yaml(root: Path) -> list[tuple[str, str]]:
    pkg = _package(root, "demo")
    _node(pkg, "talker.py", TALKER)
    (pkg / "rviz").mkdir()
    (pkg / "rviz" / "deep.rviz").write_text("Visualization Manager:\n  Displays: " + "[" * 5_000 + "]" * 5_000 + "\n")
    (pkg / "rviz" / "typed.rviz").write_text(
        "Visualization Manager:\n  Displays:\n    - {Class: {a: 1}, Topic: /scan, Enabled: true}\n"
        "    - {Class: [1], Topic: {Value: [1, 2]}}\n    - {Displays: {a: 1}, Topic: 5}\n"
        "  Tools:\n    - {Class: {x: 1}}\n    - {Class: rviz/SetGoal, Topic: {a: 1}}\n    - 7\n")
    (pkg / "params.yaml").write_text("a: " + "{b: " * 5_000 + "1" + "}" * 5_000 + "\n")
    _launch(root, "<node pkg='rviz' type='rviz' name='rviz_deep' args='-d $(find demo)/rviz/deep.rviz'/>\n"
            "<node pkg='rviz' type='rviz' name='rviz_typed' args='-d $(find demo)/rviz/typed.rviz'/>\n"
            "<node pkg='demo' type='talker.py' name='talker'><rosparam file='$(find demo)/params.yaml'/></node>")
    (root / "deep_model.yaml").write_text("models: " + "[" * 5_000 + "]" * 5_000 + "\n")
    (root / "laughs_model.yaml").write_text("package: p\nexecutable: e\nx:\n"
                                            + "".join(f"  {line}\n" for line in LAUGHS.splitlines()))
    (root / "typed_model.yaml").write_text("models:\n  - {package: p, executable: e, publishers: {a: 1}}\n"
                                           "  - {package: [1], executable: {x: 2}}\n  - 5\n")
    return [("deep.rviz", "budget-exceeded"), ("deep_model.yaml", "budget-exceeded"),
            ("laughs_model.yaml", "budget-exceeded"),
            ("typed_model.yaml", "model-schema"), ("typed.rviz", "rviz-config")]


CASES = [case_cmake_tokens, case_python_repair, case_long_names, case_cpp, case_cpp_ros2_fallback, case_deep_yaml]
OPTIONS = {case_deep_yaml: ("--launch", "src/demo/launch/main.launch", "--model", "deep_model.yaml",
                            "--model", "laughs_model.yaml", "--model", "typed_model.yaml")}


@pytest.mark.parametrize("case", CASES, ids=[c.__name__ for c in CASES])
def test_hostile_corner(tmp_path: Path, case: Callable[[Path], list[tuple[str, str]]]) -> None:
    root = tmp_path / "ws"
    root.mkdir()
    expected = case(root)
    outside = Outside(tmp_path / "outside")
    run = run_check(root, outside, *OPTIONS.get(case, ()), fmt="json")
    assert problems(run, outside) == []
    found = json.loads(run.output[run.output.index('{\n  "format"'):])["diagnostics"]
    for file, code in expected:
        assert any(d["code"] == code and file in d["file"] + d["message"] for d in found), (file, code, found)


# -- every reader, random input -----------------------------------------------------------------
SCALARS = st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | st.text(max_size=12)
KEYS = st.sampled_from(["Class", "Topic", "Value", "Enabled", "Displays", "Tools", "Visualization Manager", "models",
                        "package", "executable", "publishers", "name", "type", "qos", "if", "param", "default",
                        "ros__parameters", "launch", "node", "pkg", "exec", "args", "__line__"]) | st.text(max_size=6)
TREES = st.recursive(SCALARS, lambda inner: st.lists(inner, max_size=4) | st.dictionaries(KEYS, inner, max_size=4),
                     max_leaves=25)
TAGS = ["launch", "node", "param", "rosparam", "arg", "include", "group", "remap", "let", "env", "machine", "test",
        "executable", "set_remap", "push-ros-namespace", "package", "name", "depend", "export", "build_type"]
ATTRS = ["name", "pkg", "type", "exec", "value", "default", "file", "ns", "if", "unless", "from", "to", "command",
         "args", "param", "subst_value", "format", "output", "respawn"]


@st.composite
def xml_trees(draw: st.DrawFn, depth: int = 0) -> etree._Element:
    el = etree.Element(draw(st.sampled_from(TAGS)))
    for attr in draw(st.lists(st.sampled_from(ATTRS), max_size=3, unique=True)):
        el.set(attr, draw(st.text(alphabet=string.printable.strip() + " ", max_size=10)))
    if depth < 4:
        el.extend(draw(st.lists(xml_trees(depth + 1), max_size=3)))
    return el


DOCUMENTS = (st.binary(max_size=300) | TREES.map(lambda t: yaml.safe_dump(t).encode())
             | xml_trees().map(etree.tostring)
             | st.integers(50, 3_000).map(lambda n: ("[" * n + "]" * n).encode())
             | st.integers(50, 3_000).map(lambda n: ("a: " + "{b: " * n + "1" + "}" * n).encode())
             | st.integers(50, 3_000).map(lambda n: f"<launch>{'<group>' * n}{'</group>' * n}</launch>".encode())
             | st.just(LAUGHS.encode())
             | st.integers(1_000, 100_000).map(lambda n: ("x = " + "-" * n + "1\n").encode()))


def _launch_node(config: Path) -> LaunchNode:
    return LaunchNode(Element("e1", "main.launch", 1), "rviz", "rviz", "/rviz", "/", args=f"-d {config}")


def _with_manifest(folder: Path) -> bool:
    (folder / "package.xml").write_text(PACKAGE_XML.format("demo"))
    return True


def _read_launch(folder: Path, name: str) -> None:
    sink = DiagnosticSink()
    LaunchInterpreter(Workspace([folder], sink), sink).load([folder / name], {})


READERS: dict[str, Callable[[Path], object]] = {
    "package.xml": lambda folder: Workspace([folder], DiagnosticSink()),
    "CMakeLists.txt": lambda folder: commands((folder / "CMakeLists.txt").read_text(errors="replace"), None,
                                              lambda line, message: None),
    "setup.py": lambda folder: _with_manifest(folder) and Workspace([folder], DiagnosticSink()),
    "main.launch": lambda folder: _read_launch(folder, "main.launch"),
    "main.launch.xml": lambda folder: _read_launch(folder, "main.launch.xml"),
    "main.launch.yaml": lambda folder: _read_launch(folder, "main.launch.yaml"),
    "params.yaml": lambda folder: load_param_file(folder / "params.yaml", "params.yaml", DiagnosticSink()),
    "rosparam.yaml": lambda folder: convert((folder / "rosparam.yaml").read_text(errors="replace"), "yaml", True),
    "config.rviz": lambda folder: configured_ports(_launch_node(folder / "config.rviz"), LaunchConfig(),
                                                   Workspace([], DiagnosticSink()), DiagnosticSink()),
    "model.yaml": lambda folder: load_models(folder / "model.yaml", "model.yaml", DiagnosticSink()),
    "node.py": lambda folder: extract_python(folder / "node.py", "p", "node.py", "node.py", DiagnosticSink()),
    "Type.msg": lambda folder: members((folder / "Type.msg").read_text(errors="replace"), "p"),
}
DOCUMENTED = {"main.launch": "LaunchError", "main.launch.xml": "LaunchError", "main.launch.yaml": "LaunchError",
              "rosparam.yaml": "LaunchError"}
"""Readers whose documented failure is an exception the caller turns into a diagnostic (besides
a budget's BudgetExceeded and Crossed, which every reader may raise for its caller to report)."""


@pytest.mark.parametrize("name", list(READERS))
def test_readers_survive_random_input(name: str) -> None:
    @settings(max_examples=40, deadline=None, suppress_health_check=list(HealthCheck), database=None)
    @given(DOCUMENTS)
    def read(document: bytes) -> None:
        with tempfile.TemporaryDirectory() as folder, budget.scope():
            (Path(folder) / name).write_bytes(document)
            try:
                READERS[name](Path(folder))
            except Exception as exc:  # only the documented diagnostic path may escape
                if type(exc).__name__ != DOCUMENTED.get(name) and not isinstance(exc, (budget.BudgetExceeded,
                                                                                       budget.Crossed)):
                    raise
    read()


def test_a_macro_that_drops_its_argument_counts_once_in_nested_calls(tmp_path: Path) -> None:
    from archlog.extract.cpp.macros import defines, nested_calls
    text = "#define DROP(x) 0\n#define F(x) x x\nint f() { return DROP(F(1)) + F(DROP(2)); }\n"
    path = tmp_path / "drop.cpp"
    assert nested_calls([(path, text)], defines(path, text)) is None  # copies 0 once divided by zero
