"""What archlog reads about parameters from rclpy and rospy code (issue 29): declared types, defaults,
ParameterDescriptor ranges and read_only, required parameters, dynamic parameters; and the type of a
configured value."""

from __future__ import annotations

from pathlib import Path

import pytest

from archlog.diagnostics import DiagnosticSink
from archlog.extract.cpp.rclcpp.parameters import cpp_param_type
from archlog.extract.python.node import extract_python
from archlog.extract.summary import NodeSummary, ParamSpec
from archlog.facts.parameters import value_type

RCLPY = '''
import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter
from rcl_interfaces.msg import ParameterDescriptor, IntegerRange


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.declare_parameter("port", "/dev/ttyUSB0")
        limits = [IntegerRange(from_value=1, to_value=100)]
        self.declare_parameter("rate", 10, ParameterDescriptor(read_only=True, integer_range=limits))
        self.declare_parameter("gains", [0.1, 0.2])
        self.declare_parameter("robot_id", Parameter.Type.STRING)
        d = ParameterDescriptor()
        d.dynamic_typing = True
        self.declare_parameter("anything", 1, d)
'''


def _read(tmp_path: Path, source: str) -> NodeSummary:
    script = tmp_path / "node.py"
    script.write_text(source)
    return extract_python(script, "p", "node.py", "node.py", DiagnosticSink())


def _specs(summary: NodeSummary) -> dict[object, ParamSpec | None]:
    return {p.name: p.param for p in summary.ports if p.kind == "param_read"}


def test_rclpy_declarations(tmp_path: Path) -> None:
    summary = _read(tmp_path, RCLPY)
    assert _specs(summary) == {
        "port": ParamSpec("string", declared=True),
        "rate": ParamSpec("integer", read_only=True, bounds=((">=", "1"), ("<=", "100")), declared=True),
        "gains": ParamSpec("double_array", declared=True),
        "robot_id": ParamSpec("string", required=True, declared=True),
        "anything": ParamSpec("", declared=True),
    }
    assert summary.params_dynamic == ""


@pytest.mark.parametrize("call", [
    'super().__init__("driver", allow_undeclared_parameters=True)',
    'super().__init__("driver", automatically_declare_parameters_from_overrides=True)',
    'self.get_parameters_by_prefix("limits")',
    'self.declare_parameters("", self.names)',
])
def test_dynamic_parameters(tmp_path: Path, call: str) -> None:
    source = f"import rclpy\nfrom rclpy.node import Node\n\nclass N(Node):\n    def __init__(self):\n        {call}\n"
    assert _read(tmp_path, source).params_dynamic.startswith("node.py:6: ")


def test_rospy_required_only_outside_try_and_has_param(tmp_path: Path) -> None:
    summary = _read(tmp_path, '''
import rospy
rospy.init_node("n")
a = rospy.get_param("~a")
b = rospy.get_param("~b", 1)
try:
    c = rospy.get_param("~c")
except KeyError:
    c = 0
if rospy.has_param("~d"):
    d = rospy.get_param("~d")
''')
    assert {name: spec.required if spec else None for name, spec in _specs(summary).items()} == \
        {"~a": True, "~b": False, "~c": False, "~d": False}


def test_value_types() -> None:
    assert [value_type(v) for v in (True, 3, 0.5, "x", [1, 2], [1.0, 2], [], {"a": 1}, ["a", "b"])] == \
        ["bool", "integer", "double", "string", "integer_array", "", "", "", "string_array"]


@pytest.mark.parametrize(("spelling", "declared"), [
    ("std::basic_string<char>", "string"), ("const char *", "string"), ("long", "integer"), ("float", "double"),
    ("std::vector<std::basic_string<char>>", "string_array"),  # a vector of strings is no string (turtlebot4's menu.entries)
    ("std::vector<std::__cxx11::basic_string<char>, std::allocator<std::__cxx11::basic_string<char>>>", "string_array"),
    ("std::vector<long>", "integer_array"), ("std::vector<unsigned char>", "byte_array"),
    ("std::vector<std::vector<double>>", ""), ("std::map<int, int>", "")])
def test_the_parameter_type_a_cpp_default_declares(spelling: str, declared: str) -> None:
    assert cpp_param_type(spelling) == declared
