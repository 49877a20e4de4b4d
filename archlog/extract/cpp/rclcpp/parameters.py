"""Node parameters: declarations and their defaults, reads, writes, and values read from them.
Parameters are node-private in ROS 2: their ports and values have the handle "~"."""

from __future__ import annotations

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import K, qualified, written_args
from archlog.extract.cpp.rclcpp.api import NODE_CLASSES, PARAMETER_READS, object_of, parameter_helper
from archlog.extract.cpp.rclcpp.context import WalkContext
from archlog.values import ParamRef, Value


class Parameters:
    """Reads rclcpp's parameter API and wrappers of it (nav2's declare_parameter_if_not_declared)."""

    def __init__(self, ctx: WalkContext) -> None:
        self.ctx = ctx
        self.declared: dict[str, ci.Cursor] = {}

    def prepare_call(self, call: ci.Cursor, args: list[ci.Cursor]) -> bool:
        """Note a declaration's default, or a parameter read into a variable; True when it was one."""
        ref = call.referenced
        owner = qualified(ref.semantic_parent)
        helper = parameter_helper(ref)
        if call.spelling == "declare_parameter" and owner in NODE_CLASSES and len(args) > 1 and \
                isinstance(name := self.ctx.value(args[0]), str):
            self.declared.setdefault(name, args[1])
        elif helper is not None and helper[1] is not None and len(args) > max(helper[0], helper[1]) and \
                isinstance(name := self.ctx.value(args[helper[0]]), str):
            self.declared.setdefault(name, args[helper[1]])
        elif ref.spelling in ("get_parameter", "get_parameter_or") and owner in NODE_CLASSES and \
                len(args) == (2 if ref.spelling == "get_parameter" else 3) and \
                isinstance(name := self.ctx.value(args[0]), str):
            # get_parameter("name", variable), get_parameter_or("name", variable, alternative)
            target = next((c for c in args[1].walk_preorder() if c.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR)),
                          None)
            if target is not None:
                self.ctx.param_vars[self.ctx.key(target.referenced)] = self.parameter_value(
                    name, args[2] if len(args) == 3 else None, call)
        else:
            return False
        return True

    def read(self, call: ci.Cursor, method: str, args: list[ci.Cursor]) -> None:
        name = self.ctx.value(args[0])
        if method == "declare_parameter" and len(args) > 1 and "ParameterType" not in args[1].type.spelling:
            default: Value | None = self.ctx.value(args[1])
        elif method == "get_parameter_or" and len(args) > 1:
            default = self.ctx.value(args[-1])
        elif isinstance(name, str) and name in self.declared:
            default = self.ctx.value(self.declared[name])
        else:
            default = None
        self.ctx.add("param_read", call, name, "", "~", default)

    def helper_read(self, call: ci.Cursor, helper: tuple[int, int | None], args: list[ci.Cursor]) -> None:
        """A parameter read through a wrapper of the API, with its default or the declaration's."""
        at, default = helper
        given = args[default] if default is not None and default < len(args) else None
        pname = self.ctx.value(args[at])
        fallback = given if given is not None else self.declared.get(pname) if isinstance(pname, str) else None
        self.ctx.add("param_read", call, pname, "", "~", self.ctx.value(fallback) if fallback is not None else None)

    def write(self, call: ci.Cursor, args: list[ci.Cursor]) -> None:
        """set_parameter(rclcpp::Parameter("name", value)) and set_parameters({...})."""
        for cursor in args[0].walk_preorder():
            if cursor.kind == K.CALL_EXPR and cursor.referenced is not None and \
                    cursor.referenced.kind == K.CONSTRUCTOR and qualified(cursor.referenced.semantic_parent) == \
                    "rclcpp::Parameter" and len(pair := written_args(cursor)) == 2:
                self.ctx.add("param_write", call, self.ctx.value(pair[0]), "", "~", self.ctx.value(pair[1]))

    def parameter_value(self, name: str, default: ci.Cursor | None, call: ci.Cursor) -> ParamRef:
        """A value read from a node parameter, with its default (the declaration's, if any)."""
        default = default if default is not None else self.declared.get(name)
        fallback = self.ctx.value(default) if default is not None else \
            self.ctx.unknown(call, "parameter without default")
        return ParamRef(name, fallback, "~", self.ctx.shown(call), call.location.line)

    def call_value(self, expr: ci.Cursor, owner: str, name: str, args: list[ci.Cursor], depth: int) -> Value | None:
        """Values of rclcpp calls: parameters read, ParameterValue(x), get_name(), get_namespace()."""
        if owner in NODE_CLASSES and name in PARAMETER_READS and args and \
                isinstance(pname := self.ctx.value(args[0], depth + 1), str):
            if name == "declare_parameter":
                default = args[1] if len(args) > 1 and "ParameterType" not in args[1].type.spelling else None
            else:
                default = args[-1] if name == "get_parameter_or" and len(args) > 1 else None
            return self.parameter_value(pname, default, expr)
        if (helper := parameter_helper(expr.referenced)) is not None and helper[0] < len(args) and \
                isinstance(pname := self.ctx.value(args[helper[0]], depth + 1), str):
            given = args[helper[1]] if helper[1] is not None and helper[1] < len(args) else None
            return self.parameter_value(pname, given, expr)
        if owner in ("rclcpp::Parameter", "rclcpp::ParameterValue") and (name.startswith("as_") or name in (
                "get_value", "get", "get_parameter_value")):
            obj = object_of(expr)
            return self.ctx.value(obj, depth + 1) if obj is not None else None
        if owner == "rclcpp::ParameterValue" and expr.referenced.kind == K.CONSTRUCTOR and len(args) == 1:
            return self.ctx.value(args[0], depth + 1)
        if owner in NODE_CLASSES and name in ("get_name", "get_fully_qualified_name"):
            return "~"
        return None
