"""generate_parameter_library definitions (issue 29): the parameters an executable linking one
declares, read from the package's YAML file (types, defaults, read_only, validators, required,
mapped names), and the stand-in of the generated header its code includes."""

from __future__ import annotations

from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract import parameter_library
from archlog.extract.cpp.parameter_headers import _header
from archlog.extract.summary import NodeSummary, ParamSpec
from archlog.extract.workspace.index import Workspace

DEFINITION = """\
limiter_ns:
  speed:
    type: double
    default_value: 0.5
    read_only: true
    validation:
      bounds<>: [0.0, 2.0]
  mode:
    type: string
    default_value: clamp
    validation:
      one_of<>: [[clamp, stop]]
  robot_id:
    type: string
    description: "no default: it must be set"
  pid:
    gains:
      type: double_array_fixed_3
      default_value: [1.0, 0.0, 0.1]
      validation:
        gt_eq<>: [0.0]
    enabled:
      type: bool
      default_value: false
"""


def read(tmp_path: Path, text: str) -> tuple[NodeSummary, DiagnosticSink]:
    path = tmp_path / "limiter_parameters.yaml"
    path.write_text(text)
    summary, sink = NodeSummary("p", "limiter", "cpp"), DiagnosticSink()
    parameter_library.add_declarations(summary, [path], lambda p: Path(p).name, sink)
    return summary, sink


def test_a_definition_declares_its_parameters(tmp_path: Path) -> None:
    summary, sink = read(tmp_path, DEFINITION)
    found = {p.name: (p.default, p.param, p.line) for p in summary.ports}
    assert found == {
        "speed": ("0.5", ParamSpec("double", False, True, ((">=", "0.0"), ("<=", "2.0")), declared=True), 2),
        "mode": ("clamp", ParamSpec("string", choices=("clamp", "stop"), declared=True), 8),
        "robot_id": (None, ParamSpec("string", required=True, declared=True), 13),
        "pid.gains": ("[1.0, 0.0, 0.1]", ParamSpec("double_array", bounds=((">=", "0.0"),), declared=True), 17),
        "pid.enabled": ("false", ParamSpec("bool", declared=True), 22),
    }
    assert {p.kind for p in summary.ports} == {"param_read"} and not summary.params_dynamic and not sink.items


def test_mapped_names_make_the_parameters_dynamic(tmp_path: Path) -> None:
    summary, _sink = read(tmp_path, "ns:\n  joints:\n    type: string_array\n    default_value: []\n"
                                    "  __map_joints:\n    gain:\n      type: double\n      default_value: 1.0\n")
    assert [p.name for p in summary.ports] == ["joints"]
    assert "names other parameters give" in summary.params_dynamic


def test_a_broken_definition_is_a_diagnostic_and_the_node_is_not_judged(tmp_path: Path) -> None:
    summary, sink = read(tmp_path, "ns:\n  speed: [unclosed\n")
    assert [(d.file, d.code) for d in sink.items] == [("limiter_parameters.yaml", "param-library")]
    assert summary.ports == [] and summary.params_dynamic.startswith("limiter_parameters.yaml:")
    summary, sink = read(tmp_path, "- a list\n")
    assert "one top key" in sink.items[0].message and summary.params_dynamic


def test_the_stand_in_header_has_the_struct_and_the_listener() -> None:
    text = _header("limiter_ns", {"speed": {"type": "double"}, "pid.gains": {"type": "double_array_fixed_3"},
                                  "pid.enabled": {"type": "bool"}, "robot_id": {"type": "string"}})
    assert "namespace limiter_ns {" in text and "class ParamListener {" in text
    assert "  double speed{};\n" in text and "  std::string robot_id{};\n" in text
    assert "  struct Pid_ {\n    std::vector<double> gains{};\n    bool enabled{};\n  } pid;\n" in text


def test_cmake_links_the_definition_to_the_executable(tmp_path: Path) -> None:
    pkg = tmp_path / "limiter"
    (pkg / "src").mkdir(parents=True)
    (pkg / "package.xml").write_text("<package format='3'><name>limiter</name><version>1.0.0</version>"
                                     "<description>d</description><maintainer email='a@example.com'>a</maintainer>"
                                     "<license>MIT</license><buildtool_depend>ament_cmake</buildtool_depend>"
                                     "</package>\n")
    (pkg / "CMakeLists.txt").write_text(
        "project(limiter)\ngenerate_parameter_library(limiter_parameters src/limiter_parameters.yaml)\n"
        "add_library(core src/core.cpp)\ntarget_link_libraries(core limiter_parameters)\n"
        "add_executable(limiter src/main.cpp)\ntarget_link_libraries(limiter core)\n"
        "add_executable(other src/other.cpp)\n")
    for name in ("core.cpp", "main.cpp", "other.cpp", "limiter_parameters.yaml"):
        (pkg / "src" / name).write_text("")
    workspace = Workspace([tmp_path], DiagnosticSink())
    assert workspace.executable("limiter", "limiter").parameter_files == [pkg / "src" / "limiter_parameters.yaml"]
    assert workspace.executable("limiter", "other").parameter_files == []


def test_rclcpp_descriptor_ranges_and_read_only_are_read() -> None:
    """ParameterDescriptor ranges (a range variable pushed back or braced in, bounds set by
    assignment or by the set__ chain) and read_only, from the C++ corpus twin."""
    from conftest import CORPUS_ROS2

    from archlog.analysis import analyse

    store = analyse([CORPUS_ROS2 / "param_descriptor_range_cpp" / "buggy"], ["arm_guard/launch/guard.launch.py"],
                    {}, []).store
    names = {str(port): str(name) for port, _node, name, _default in store.rows("param_read")}
    bounds = sorted((names[str(port)], str(op), str(bound)) for port, op, bound in store.rows("param_bound"))
    assert bounds == [("/arm_guard/joint_count", "<=", "7"), ("/arm_guard/joint_count", ">=", "1"),
                      ("/arm_guard/max_effort", "<=", "40.0"), ("/arm_guard/max_effort", ">=", "0.0")]
    assert [names[str(port)] for (port,) in store.rows("param_read_only")] == ["/arm_guard/joint_count"]
