"""What rclpy and rospy code says about a parameter beyond its name and default (the declared type,
whether any default exists, a ParameterDescriptor's read_only and ranges), and the calls that make a
node's parameters dynamic (accepted or read under names not known statically)."""

from __future__ import annotations

import ast
from collections.abc import Callable

from archlog.extract.python.index import arg
from archlog.extract.summary import ParamSpec
from archlog.values import Value

_SCALARS: tuple[tuple[type, str], ...] = ((bool, "bool"), (int, "integer"), (float, "double"), (str, "string"),
                                          (bytes, "byte_array"))
_TYPE_NAMES = {"BOOL": "bool", "INTEGER": "integer", "DOUBLE": "double", "STRING": "string",
               "BYTE_ARRAY": "byte_array", "BOOL_ARRAY": "bool_array", "INTEGER_ARRAY": "integer_array",
               "DOUBLE_ARRAY": "double_array", "STRING_ARRAY": "string_array"}
# rclpy Node options that accept parameters the node never declares
_DYNAMIC_OPTIONS = ("allow_undeclared_parameters", "automatically_declare_parameters_from_overrides")
# calls that read parameters whose names the code does not spell: rclpy Node methods, rospy functions and classes
_DYNAMIC_METHODS = ("get_parameters_by_prefix", "list_parameters")
_DYNAMIC_FUNCTIONS = ("rospy.get_param_names", "dynamic_reconfigure.server.Server")

Qualify = Callable[[ast.expr], "str | None"]


def literal_type(expr: ast.expr | None, qualified: Qualify) -> str:
    """The ROS 2 parameter type a default written as a literal (or `Parameter.Type.X`) gives; "" otherwise."""
    if isinstance(expr, ast.UnaryOp) and isinstance(expr.op, (ast.USub, ast.UAdd)):
        expr = expr.operand
    if isinstance(expr, ast.Constant):
        return next((name for kind, name in _SCALARS if type(expr.value) is kind), "")
    if isinstance(expr, (ast.List, ast.Tuple)) and expr.elts:
        kinds = {literal_type(e, qualified) for e in expr.elts}
        return f"{kinds.pop()}_array" if len(kinds) == 1 and kinds <= {"bool", "integer", "double", "string"} else ""
    if isinstance(expr, ast.Attribute) and (qualified(expr) or "").rsplit(".", 2)[-2:-1] == ["Type"]:
        return _TYPE_NAMES.get(expr.attr, "")
    return ""


class ParamReader:
    """Reads parameter declarations in one module; `value` folds an expression to its text."""

    def __init__(self, tree: ast.Module, qualified: Qualify, value: Callable[[ast.expr], Value]) -> None:
        self.qualified = qualified
        self.value = value
        self.assigned: dict[str, list[ast.expr]] = {}  # target as written -> the values assigned to it
        self.guarded: list[tuple[int, int]] = []  # lines of try blocks (a missing parameter may be caught)
        self.tested: set[str] = set()  # names rospy.has_param asks about
        for node in ast.walk(tree):
            if isinstance(node, ast.Assign):
                for target in node.targets:
                    self.assigned.setdefault(ast.unparse(target), []).append(node.value)
            elif isinstance(node, ast.Try) and node.handlers:
                self.guarded.append((node.body[0].lineno, node.body[-1].end_lineno or node.body[-1].lineno))
            elif isinstance(node, ast.Call) and qualified(node.func) == "rospy.has_param" and node.args:
                self.tested.add(ast.unparse(node.args[0]))

    def declaration(self, call: ast.Call, default: ast.expr | None, descriptor: ast.expr | None) -> ParamSpec:
        """An rclpy declaration: `declare_parameter(name, value, descriptor)` or a declare_parameters tuple."""
        fields = self._fields(descriptor)
        dynamic = self._true(fields.get("dynamic_typing"))
        type_name = "" if dynamic else literal_type(default, self.qualified)
        is_type = isinstance(default, ast.Attribute) and type_name != ""
        required = default is None or is_type or (isinstance(default, ast.Constant) and default.value is None)
        bounds: list[tuple[str, str]] = []
        for key in ("floating_point_range", "integer_range"):
            for item in self._items(fields.get(key)):
                ranged = self._fields(item)
                for field, op in (("from_value", ">="), ("to_value", "<=")):
                    if field in ranged and isinstance(bound := self.value(ranged[field]), str):
                        bounds.append((op, bound))
        return ParamSpec(type_name, required and not dynamic, self._true(fields.get("read_only")), tuple(bounds),
                         declared=True)

    def rospy_read(self, call: ast.Call) -> ParamSpec:
        """rospy.get_param without a default raises KeyError when the parameter is not set: required,
        unless the call sits in a try block or rospy.has_param asks about the name first."""
        if arg(call, 1, "default") is not None or not call.args:
            return ParamSpec()
        caught = any(start <= call.lineno <= end for start, end in self.guarded)
        return ParamSpec(required=not caught and ast.unparse(call.args[0]) not in self.tested)

    def dynamic(self, call: ast.Call, func: str | None, method: str | None, on_node: bool) -> str | None:
        """Why this call makes the node's parameters dynamic, or None."""
        if func in _DYNAMIC_FUNCTIONS:
            return f"{func}() reads parameters by names the code does not spell"
        if on_node and method in _DYNAMIC_METHODS:
            return f"{method}() reads parameters by names the code does not spell"
        if on_node and method == "declare_parameters" and not isinstance(arg(call, 1, "parameters"),
                                                                         (ast.List, ast.Tuple)):
            return "declare_parameters() with a list not known statically"
        for keyword in call.keywords:
            if keyword.arg in _DYNAMIC_OPTIONS and not (isinstance(keyword.value, ast.Constant)
                                                        and keyword.value.value is False):
                return f"{keyword.arg}: the node accepts parameters it does not declare"
        return None

    def _fields(self, expr: ast.expr | None) -> dict[str, ast.expr]:
        """The keyword fields of a message constructed inline, or of a variable assigned one (with the
        fields later assigned to it: `d.read_only = True`)."""
        if isinstance(expr, (ast.Name, ast.Attribute)):
            written = ast.unparse(expr)
            values = self.assigned.get(written, [])
            fields = self._fields(values[0]) if len(values) == 1 else {}
            prefix = written + "."
            for target, assigned in self.assigned.items():
                if target.startswith(prefix) and "." not in target[len(prefix):] and len(assigned) == 1:
                    fields[target[len(prefix):]] = assigned[0]
            return fields
        if isinstance(expr, ast.Call):
            return {kw.arg: kw.value for kw in expr.keywords if kw.arg}
        return {}

    def _items(self, expr: ast.expr | None) -> list[ast.expr]:
        if isinstance(expr, (ast.Name, ast.Attribute)) and len(values := self.assigned.get(ast.unparse(expr), [])) == 1:
            expr = values[0]
        return list(expr.elts) if isinstance(expr, (ast.List, ast.Tuple)) else []

    @staticmethod
    def _true(expr: ast.expr | None) -> bool:
        return isinstance(expr, ast.Constant) and expr.value is True


def declared_pair(item: ast.expr) -> tuple[ast.expr, ast.expr | None, ast.expr | None]:
    """One entry of declare_parameters' list: (name,), (name, value) or (name, value, descriptor)."""
    pair = item.elts if isinstance(item, ast.Tuple) else [item]
    return pair[0], pair[1] if len(pair) > 1 else None, pair[2] if len(pair) > 2 else None
