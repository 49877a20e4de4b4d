"""Node parameters: declarations and their defaults, reads, writes, and values read from them.
Parameters are node-private in ROS 2: their ports and values have the handle "~"."""

from __future__ import annotations

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import K, qualified, written_args
from archlog.extract.cpp.rclcpp.api import NODE_CLASSES, PARAMETER_READS, object_of, parameter_helper
from archlog.extract.cpp.rclcpp.context import WalkContext
from archlog.extract.summary import ParamSpec
from archlog.values import ParamRef, Value

_INTEGERS = {"int", "long", "long long", "short", "unsigned int", "unsigned long", "unsigned long long",
             "unsigned short", "signed char", "unsigned char"}
_ARRAYS = {"bool": "bool_array", "integer": "integer_array", "double": "double_array", "string": "string_array"}
# NodeOptions settings that make a node accept parameters it never declares, and reads of parameters by prefix
_DYNAMIC_OPTIONS = ("allow_undeclared_parameters", "automatically_declare_parameters_from_overrides")
_DYNAMIC_READS = ("get_parameters_by_prefix", "list_parameters")


def cpp_param_type(spelling: str) -> str:
    """The ROS 2 parameter type a C++ value type (canonical spelling) declares; "" when none does."""
    bare = spelling.replace("const ", "").replace("&", "").strip()
    if bare == "bool":
        return "bool"
    if bare in _INTEGERS:
        return "integer"
    if bare in ("double", "float"):
        return "double"
    if bare.startswith("std::vector<"):  # before the string test: a vector of strings spells basic_string<char too
        element = bare[len("std::vector<"):].split(",", 1)[0].rstrip(">").strip()
        nested = element.startswith("std::vector<")
        return "" if nested else "byte_array" if element == "unsigned char" else _ARRAYS.get(cpp_param_type(element), "")
    if "basic_string<char" in bare or bare.startswith("char *") or bare.startswith("char["):
        return "string"
    return ""


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
        spec = self.declaration(call, args) if method == "declare_parameter" else None
        if method == "declare_parameter" and len(args) > 1 and "ParameterType" not in args[1].type.spelling:
            default: Value | None = self.ctx.value(args[1])
        elif method == "get_parameter_or" and len(args) > 1:
            default = self.ctx.value(args[-1])
        elif isinstance(name, str) and name in self.declared:
            default = self.ctx.value(self.declared[name])
        else:
            default = None
        self.ctx.add("param_read", call, name, "", "~", default, param=spec)

    def helper_read(self, call: ci.Cursor, helper: tuple[int, int | None], args: list[ci.Cursor]) -> None:
        """A parameter read through a wrapper of the API, with its default or the declaration's."""
        at, default = helper
        given = args[default] if default is not None and default < len(args) else None
        pname = self.ctx.value(args[at])
        fallback = given if given is not None else self.declared.get(pname) if isinstance(pname, str) else None
        spec = ParamSpec(self._type_of(given), declared=True) if given is not None and \
            call.referenced.spelling.startswith("declare") else None
        self.ctx.add("param_read", call, pname, "", "~", self.ctx.value(fallback) if fallback is not None else None,
                     param=spec)

    def declaration(self, call: ci.Cursor, args: list[ci.Cursor]) -> ParamSpec:
        """declare_parameter's type (of its default, its template argument or a ParameterType) and whether it
        has a default at all."""
        second = args[1].type.spelling if len(args) > 1 else ""
        if "ParameterType" in second:
            kind = next((t.spelling for t in args[1].get_tokens() if t.spelling.startswith("PARAMETER_")), "")
            return ParamSpec(kind[len("PARAMETER_"):].lower() if kind != "PARAMETER_NOT_SET" else "", required=True,
                             declared=True)
        returned = cpp_param_type(call.type.get_canonical().spelling)
        described = next((a for a in args[1:] if "ParameterDescriptor" in a.type.spelling), None)
        read_only, bounds = descriptor(described) if described is not None else (False, ())
        if len(args) < 2 or "ParameterDescriptor" in second:
            return ParamSpec(returned, required=True, read_only=read_only, bounds=bounds, declared=True)
        return ParamSpec(returned or self._type_of(args[1]), read_only=read_only, bounds=bounds, declared=True)

    def _type_of(self, value: ci.Cursor) -> str:
        """The parameter type of a default: its own type, or the one a ParameterValue is built from."""
        spelling = value.type.get_canonical().spelling
        if "ParameterValue" in spelling:
            inner = [c for c in value.walk_preorder() if c.kind in (K.CALL_EXPR, K.CXX_FUNCTIONAL_CAST_EXPR)
                     and "ParameterValue" in c.type.spelling and len(written_args(c)) == 1]
            return cpp_param_type(written_args(inner[0])[0].type.get_canonical().spelling) if inner else ""
        return cpp_param_type(spelling)

    def dynamic(self, call: ci.Cursor, owner: str, name: str, args: list[ci.Cursor]) -> bool:
        """NodeOptions().allow_undeclared_parameters(true) and the like, and reads of parameters by prefix:
        the node's parameters are not all known; True when the call was one."""
        if owner == "rclcpp::NodeOptions" and name in _DYNAMIC_OPTIONS and args and \
                self.ctx.value(args[0]) not in ("false", "0"):
            why = f"NodeOptions::{name}: the node accepts parameters it does not declare"
        elif owner in NODE_CLASSES and (name in _DYNAMIC_READS or (name == "get_parameters" and len(args) == 2)):
            why = f"{name}() reads parameters by names the code does not spell"
        else:
            return False
        self.ctx.result.params_dynamic = self.ctx.result.params_dynamic or \
            f"{self.ctx.shown(call)}:{call.location.line}: {why}"
        return True

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


_RANGES = ("floating_point_range", "integer_range")
_ENDS = {"from_value": ">=", "to_value": "<=", "set__from_value": ">=", "set__to_value": "<="}


def descriptor(arg: ci.Cursor) -> tuple[bool, tuple[tuple[str, str], ...]]:
    """read_only and the range bounds of a ParameterDescriptor variable passed to
    declare_parameter, from the statements of its function that set them: `d.read_only = true;`,
    `d.floating_point_range[0].from_value = 0.0;`, and a FloatingPointRange/IntegerRange variable
    `r` (`r.from_value = 0.0;`, `r.set__from_value(0.0).set__to_value(1.0);`) that
    `d.floating_point_range.push_back(r)` or `d.integer_range = {r}` adds. Anything else (a
    descriptor built elsewhere, a bound that is not a number literal) adds nothing."""
    ref = next((c.referenced for c in arg.walk_preorder() if c.kind == K.DECL_REF_EXPR), None)
    if ref is None or ref.kind != K.VAR_DECL or ref.semantic_parent is None:
        return False, ()
    name, statements = ref.spelling, _statements(ref.semantic_parent)
    read_only = any(s[:5] == [name, ".", "read_only", "=", "true"] for s in statements)
    added = {word for s in statements if s[:2] == [name, "."] and len(s) > 2 and s[2] in _RANGES
             for word in s[3:] if word.isidentifier() and word not in ("push_back", "emplace_back", "resize")}
    bounds = [bound for s in statements if (s[:2] == [name, "."] and len(s) > 2 and s[2] in _RANGES)
              or (s and s[0] in added) for bound in _bounds(s)]
    return read_only, tuple(dict.fromkeys(bounds))


def _statements(function: ci.Cursor) -> list[list[str]]:
    """The token spellings of a function's statements (split at `;`)."""
    statements: list[list[str]] = [[]]
    for token in function.get_tokens():
        if token.spelling == ";":
            statements.append([])
        else:
            statements[-1].append(token.spelling)
    return statements


def _bounds(statement: list[str]) -> list[tuple[str, str]]:
    """`from_value = N`, `to_value = N`, `set__from_value(N)`, `set__to_value(N)` in a statement."""
    found = []
    for i, word in enumerate(statement[:-2]):
        if word in _ENDS and statement[i + 1] in ("=", "("):
            sign = "-" if statement[i + 2] == "-" else ""
            number = statement[i + 3] if sign and i + 3 < len(statement) else statement[i + 2]
            literal = number.rstrip("fFlLuU")
            try:
                float(literal)
            except ValueError:
                continue
            found.append((_ENDS[word], sign + literal))
    return found
