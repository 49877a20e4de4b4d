"""State in C++ behavior: the members and globals a condition tests (guards) and the values an
assignment gives them (state writes), in summary.STATE_VALUES' vocabulary.

A state variable is named `Class::member_` or by the global's name, with `.field` for a part of
it (`Planner::path_.poses`); locals and parameters are not state."""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import SKIP, K, binary_operator, strip, unary_operator, written_args

_GLOBAL_SCOPES = (K.TRANSLATION_UNIT, K.NAMESPACE, K.UNEXPOSED_DECL, K.LINKAGE_SPEC)
_CLASSES = (K.CLASS_DECL, K.STRUCT_DECL, K.CLASS_TEMPLATE, K.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION)
_SMART = re.compile(r"^(?:const )?(?:std|boost)::(?:__\w+::)?(?:shared_ptr|unique_ptr|optional)<")
_CONTAINER = re.compile(r"^(?:const )?(?:std::(?:__\w+::)?(?:vector|deque|list|forward_list|map|multimap|set|multiset|"
                        r"unordered_\w+|basic_string|queue|stack|priority_queue)|boost::circular_buffer|"
                        r"Eigen::Matrix)<")
_LITERALS = (K.INTEGER_LITERAL, K.FLOATING_LITERAL, K.CXX_BOOL_LITERAL_EXPR, K.STRING_LITERAL, K.CHARACTER_LITERAL)
_NULLS = (K.CXX_NULL_PTR_LITERAL_EXPR, K.GNU_NULL_EXPR)
FACTORIES = ("make_shared", "make_unique", "allocate_shared", "make_optional")
GROW = ("push_back", "emplace_back", "push_front", "emplace_front", "push", "insert", "emplace", "assign", "append")
SHRINK = ("clear", "erase", "pop_back", "pop_front", "pop")
CONTAINER_WRITES = (*GROW, *SHRINK, "resize", "swap")
POINTER_WRITES = ("reset", "emplace", "swap")
# negating a comparison: not (a < b) is a >= b
_NEGATED = {"==": "!=", "!=": "==", "<": ">=", ">=": "<", ">": "<=", "<=": ">"}
_SWAPPED = {"==": "==", "!=": "!=", "<": ">", ">": "<", "<=": ">=", ">=": "<="}


@dataclass(frozen=True)
class StateVar:
    """A member or global, or a part of one (`name` has the parts after a dot), and the shape of
    its (last part's) type: bool, pointer, container, object or scalar."""

    name: str
    decl: ci.Cursor
    shape: str

    @property
    def whole(self) -> bool:
        return "." not in self.name.rsplit("::", 1)[-1]


Atom = tuple[StateVar, str]  # a state variable and the value a condition requires


def shape(type_: ci.Type) -> str:
    canonical = type_.get_canonical()
    if canonical.kind == ci.TypeKind.LVALUEREFERENCE:
        canonical = canonical.get_pointee().get_canonical()
    spelling = canonical.spelling
    if canonical.kind == ci.TypeKind.BOOL:
        return "bool"
    if canonical.kind == ci.TypeKind.POINTER or _SMART.match(spelling):
        return "pointer"
    if _CONTAINER.match(spelling):
        return "container"
    return "object" if canonical.kind == ci.TypeKind.RECORD else "scalar"


def state_var(expr: ci.Cursor, depth: int = 0) -> StateVar | None:
    """The member (of `this`) or global an expression names, or a field path into one."""
    expr = strip(expr)
    if depth > 6:
        return None
    if expr.kind in (K.MEMBER_REF_EXPR, K.MEMBER_REF):  # MEMBER_REF: in a constructor's initializer list
        ref = expr.referenced
        if ref is None or ref.kind not in (K.FIELD_DECL, K.VAR_DECL):
            return None
        base = next((c for c in expr.get_children() if c.kind not in SKIP), None)
        base = strip(base) if base is not None else None
        if ref.kind == K.VAR_DECL or base is None or base.kind == K.CXX_THIS_EXPR:
            owner = ref.semantic_parent.spelling if ref.semantic_parent is not None else ""
            return StateVar(f"{owner}::{ref.spelling}" if owner else ref.spelling, ref, shape(ref.type))
        inner = state_var(base, depth + 1)
        return StateVar(f"{inner.name}.{ref.spelling}", inner.decl, shape(ref.type)) if inner else None
    if expr.kind == K.DECL_REF_EXPR:
        ref = expr.referenced
        parent = ref.semantic_parent if ref is not None and ref.kind == K.VAR_DECL else None
        if parent is None:
            return None
        if parent.kind in _GLOBAL_SCOPES:
            return StateVar(ref.spelling, ref, shape(ref.type))
        if parent.kind in _CLASSES:  # a static member
            return StateVar(f"{parent.spelling}::{ref.spelling}", ref, shape(ref.type))
    return None


def object_of(call: ci.Cursor) -> ci.Cursor | None:
    """`x` in `x.method(...)` or `x->method(...)`."""
    callee = next(call.get_children(), None)
    if callee is not None and callee.kind == K.MEMBER_REF_EXPR:
        return next((c for c in callee.get_children() if c.kind not in SKIP), None)
    return None


def operands(call: ci.Cursor) -> list[ci.Cursor]:
    """The operands of an overloaded operator call (`a == b`, `a = b` on class types)."""
    return [c for c in call.get_children() if not (c.kind in (K.UNEXPOSED_EXPR, K.DECL_REF_EXPR)
                                                   and c.spelling.startswith("operator"))]


def comparison(expr: ci.Cursor) -> tuple[str, ci.Cursor, ci.Cursor] | None:
    if expr.kind == K.BINARY_OPERATOR:
        op = binary_operator(expr)
        children = list(expr.get_children())
        return (op, children[0], children[1]) if op in _NEGATED and len(children) == 2 else None
    if expr.kind == K.CALL_EXPR and expr.spelling.startswith("operator") and expr.spelling[8:] in _NEGATED:
        parts = operands(expr)
        return (expr.spelling[8:], parts[0], parts[1]) if len(parts) == 2 else None
    return None


def constant(expr: ci.Cursor, depth: int = 0) -> str | None:
    """The text of a constant: an enumerator as Enum::NAME, a literal as written, a constant
    variable's value; None for anything else."""
    expr = strip(expr)
    if depth > 4:
        return None
    if expr.kind in _LITERALS:
        return "".join(t.spelling for t in expr.get_tokens()) or None
    if expr.kind == K.UNARY_OPERATOR and unary_operator(expr) == "-":
        inner = constant(next(expr.get_children()), depth + 1)
        return f"-{inner}" if inner is not None else None
    if expr.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and expr.referenced is not None:
        ref = expr.referenced
        if ref.kind == K.ENUM_CONSTANT_DECL:
            enum = ref.semantic_parent.spelling if ref.semantic_parent is not None else ""
            return f"{enum}::{ref.spelling}" if enum and "(" not in enum else ref.spelling
        init = [c for c in ref.get_children() if c.kind not in SKIP]
        if ref.kind == K.VAR_DECL and init and ref.type.is_const_qualified():
            return constant(init[-1], depth + 1)
    if expr.kind == K.CALL_EXPR and len(args := written_args(expr)) == 1 and expr.referenced is not None and \
            expr.referenced.kind == K.CONSTRUCTOR:
        return constant(args[0], depth + 1)
    return None


def is_null(expr: ci.Cursor) -> bool:
    expr = strip(expr)
    return expr.kind in _NULLS or (expr.kind == K.INTEGER_LITERAL and constant(expr) == "0") or \
        (expr.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and expr.spelling in ("nullopt", "none"))


class Conditions:
    """Conditions read as the state they require: `atoms(cond, True)` is what holds when `cond`
    is true, `atoms(cond, False)` when it is false (only what holds for sure)."""

    def __init__(self, endless: Callable[[ci.Cursor], bool],
                 targets: Callable[[ci.Cursor], list[ci.Cursor]]) -> None:
        self.endless = endless  # ros::ok() and the like: true while the node runs
        self.targets = targets  # the definitions a call may run (a virtual method's overrides)

    def atoms(self, expr: ci.Cursor, positive: bool, depth: int = 0) -> list[Atom]:
        expr = strip(expr)
        if depth > 8:
            return []
        kind = expr.kind
        if kind == K.UNARY_OPERATOR and unary_operator(expr) == "!":
            return self.atoms(next(expr.get_children()), not positive, depth + 1)
        if kind == K.BINARY_OPERATOR and (op := binary_operator(expr)) in ("&&", "||"):
            parts = [c for c in expr.get_children() if not self.endless(c)]
            if (op == "&&") == positive or len(parts) == 1:
                return [a for part in parts for a in self.atoms(part, positive, depth + 1)]
            return []
        if (compared := comparison(expr)) is not None:
            op, left, right = compared
            return self.compare(op if positive else _NEGATED[op], left, right)
        if kind == K.CALL_EXPR:
            return self.call(expr, positive, depth)
        var = state_var(expr)
        if var is not None and var.shape == "bool":
            return [(var, "true" if positive else "false")]
        if var is not None and var.shape == "pointer":
            return [(var, "set" if positive else "unset")]
        return []

    def call(self, call: ci.Cursor, positive: bool, depth: int) -> list[Atom]:
        name, obj = call.spelling, object_of(call)
        var = state_var(obj) if obj is not None else None
        if var is not None and name == "empty":
            return [(var, "empty" if positive else "nonempty")]
        if var is not None and name in ("size", "length"):
            return [(var, "nonempty" if positive else "empty")]
        if var is not None and name in ("operator bool", "has_value", "is_initialized", "get"):
            return [(var, "set" if positive else "unset")]
        if written_args(call) or depth >= 3:
            return []
        found: list[Atom] | None = None
        for definition in self.targets(call):  # what holds whichever of them runs
            body = single_return(definition)
            atoms = self.atoms(body, positive, depth + 1) if body is not None else []
            found = atoms if found is None else [a for a in found if (a[0].name, a[1]) in
                                                  {(b[0].name, b[1]) for b in atoms}]
        return found or []

    @staticmethod
    def compare(op: str, left: ci.Cursor, right: ci.Cursor) -> list[Atom]:
        """`var OP other` (either side), `var.size() OP n`."""
        var = state_var(left)
        if var is None and (var := state_var(right)) is not None:
            op, left, right = _SWAPPED[op], right, left
        if var is not None:
            if var.shape == "pointer" and is_null(right) and op in ("==", "!="):
                return [(var, "unset" if op == "==" else "set")]
            value = constant(right)
            if value in ("true", "false") and op in ("==", "!="):
                return [(var, value if op == "==" else {"true": "false", "false": "true"}[value])]
            return [(var, value)] if value is not None and op == "==" else []
        sized = strip(left)
        obj = object_of(sized) if sized.kind == K.CALL_EXPR and sized.spelling in ("size", "length") else None
        container = state_var(obj) if obj is not None else None
        bound = constant(right)
        if container is None or bound is None or not bound.isdigit():
            return []
        n = int(bound)
        if (op == "==" and n == 0) or (op == "<=" and n == 0) or (op == "<" and n == 1):
            return [(container, "empty")]
        if (op == "!=" and n == 0) or op == ">" or (op == ">=" and n >= 1) or (op == "==" and n > 0):
            return [(container, "nonempty")]
        return []


def single_return(definition: ci.Cursor) -> ci.Cursor | None:
    """The returned expression of a function whose body is one return statement
    (`bool ready() const { return has_pose_ && has_map_; }`)."""
    body = next((c for c in definition.get_children() if c.kind == K.COMPOUND_STMT), None)
    statements = list(body.get_children()) if body is not None else []
    if len(statements) == 1 and statements[0].kind == K.RETURN_STMT:
        return next(statements[0].get_children(), None)
    return None


def assigned_value(var: StateVar, rhs: ci.Cursor | None) -> str:
    """What `var = rhs` makes of a state variable (rhs None: default-constructed)."""
    if rhs is None:
        return {"pointer": "unset", "container": "empty"}.get(var.shape, "?")
    expr = strip(rhs)
    if var.shape == "bool":
        value = constant(expr)
        return {"true": "true", "false": "false", "1": "true", "0": "false"}.get(value or "", "?")
    if var.shape == "pointer":
        if is_null(expr):
            return "unset"
        if expr.kind == K.CXX_NEW_EXPR or (expr.kind == K.CALL_EXPR and expr.spelling in FACTORIES):
            return "set"
        if expr.kind == K.CALL_EXPR and expr.spelling == "move" and written_args(expr):
            expr = strip(written_args(expr)[0])
        if expr.kind == K.DECL_REF_EXPR and expr.referenced is not None and expr.referenced.kind == K.PARM_DECL \
                and shape(expr.referenced.type) == "pointer":
            return "set"  # a callback's message
        if "optional" in var.decl.type.spelling and shape(expr.type) != "pointer":
            return "set"
        return "?"
    if var.shape == "container":
        if (expr.kind == K.INIT_LIST_EXPR and not list(expr.get_children())) or \
                (expr.kind == K.CALL_EXPR and not written_args(expr) and expr.referenced is not None
                 and expr.referenced.kind == K.CONSTRUCTOR):
            return "empty"
        if expr.kind == K.STRING_LITERAL:  # a std::string compared with constants
            return "empty" if expr.spelling == '""' else constant(expr) or "?"
        return "?"
    return constant(expr) or "?"


def method_value(var: StateVar, method: str, args: list[ci.Cursor]) -> str | None:
    """What calling `method` on a state variable makes of it (None: not a write)."""
    if var.shape == "pointer" and method in POINTER_WRITES:
        if method == "reset":
            return assigned_value(var, args[0]) if args else "unset"
        return "set" if method == "emplace" else "?"
    if var.shape in ("container", "object") and method in CONTAINER_WRITES:
        if method in GROW:
            return "nonempty"
        if method in SHRINK:  # may leave it empty, never makes it nonempty
            return "empty"
        if method == "resize" and args and (size := constant(args[0])) is not None and size.isdigit():
            return "empty" if size == "0" else "nonempty"
        return "?"
    return None


def initial_value(var: StateVar) -> str | None:
    """A member's or global's value before any code runs: its initializer, else what default
    construction gives (empty containers, null smart pointers; globals are zeroed); None when
    a constructor decides (the caller looks there)."""
    decl = var.decl
    init = [c for c in decl.get_children() if c.kind not in SKIP and c.kind != K.ANNOTATE_ATTR]
    init = [c for c in init if not (c.kind == K.CALL_EXPR and not written_args(c))]  # default construction
    is_global = decl.kind == K.VAR_DECL
    if var.whole:
        if init:
            value = init[-1]
            if value.kind == K.INIT_LIST_EXPR and len(items := list(value.get_children())) == 1 and \
                    var.shape != "container":
                value = items[0]
            return assigned_value(var, value)
        smart = var.shape == "pointer" and decl.type.get_canonical().kind != ci.TypeKind.POINTER
        if var.shape == "container" or smart:
            return assigned_value(var, None)
        if is_global:
            return {"bool": "false", "pointer": "unset", "scalar": "0"}.get(var.shape)
        return None
    if init:
        return "?"
    return {"container": "empty", "pointer": "unset", "bool": "false"}.get(var.shape, "?")
