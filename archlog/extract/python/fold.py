"""Folding Python expressions to values: literals, module and class constants, `self`
attributes, f-strings, `%` and `.format`, `+`, parameter reads, the node's namespace, and function or
`__init__` parameters whose call sites in the file agree (a small function summary). Loop variables
take the element a walk binds them to (`bound`) or, folded elsewhere, every element of the sequence.
A variable one function assigns several times is followed through that function in order
(`in_order`: a parameter read in try/except KeyError, an `if` on the value itself); a function's
parameters are bound per call site when the walk visits it once per call (node.py).
Anything else is an explicit Unknown with file:line.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass, replace

from archlog.extract.python.index import Assigned, FileIndex, Function, arg, is_self_attr
from archlog.values import Namespace, ParamList, ParamRef, Switch, Unknown, Value, alternatives, concat

_PARAMETER_VALUES = {"value", "string_value", "integer_value", "double_value", "bool_value"}
_KIND = {ast.AugAssign: "augmented assignment", ast.For: "loop variable", ast.With: "with target"}
_SAME_ELEMENTS = {"list", "tuple", "sorted", "reversed"}  # calls whose result has the elements of their argument
_MISSING_PARAMETER = {"KeyError", "Exception", "BaseException"}  # what rospy.get_param raises for a parameter not set


class _NotInOrder(Exception):
    """The statements assigning a variable do more than in_order() follows."""


@dataclass(frozen=True)
class Element:
    """One element of a sequence a loop walks: an expression of the file, folded in `scope`, or
    (`expr` None) a value: an element of a list parameter, or an unknown element; or the tuple of
    `parts` that enumerate() and zip() make."""

    expr: ast.expr | None
    scope: Function | None
    value: Value | None = None
    parts: tuple[Element, ...] | None = None


class ValueFolder(FileIndex):
    """The values of a file's expressions; `scope` is the function a walk is in (an expression
    folded without a scope folds in it); `bound` holds the loop variables a walk has bound to one
    element, by the function they are bound in (its node's id; None at module level) and name."""

    def __init__(self, file: str, tree: ast.Module) -> None:
        self.bound: dict[tuple[int | None, str], Element] = {}
        self.scope: Function | None = None
        self.current: dict[tuple[int, str], Value] = {}  # a variable's value so far, while in_order() runs
        super().__init__(tree)
        self.file = file

    @staticmethod
    def key_of(name: str, scope: Function | None) -> tuple[int | None, str]:
        """The key of a loop variable in `bound`."""
        return id(scope.node) if scope else None, name

    def binding(self, name: str, scope: Function | None) -> Element | None:
        """The element a walk bound a loop variable to in a function, if any."""
        return self.bound.get(self.key_of(name, scope))

    def qualified(self, expr: ast.expr) -> str | None:
        """The dotted name of an expression; a bound loop variable's is its element's."""
        if isinstance(expr, ast.Name) and (item := self.binding(expr.id, self.scope)) is not None:
            return self.qualified(item.expr) if item.expr is not None else None
        return super().qualified(expr)

    def elements(self, expr: ast.expr, scope: Function | None, depth: int = 0) -> list[Element] | ParamList | Unknown:
        """The elements of a sequence a loop walks: a literal list, tuple or set (directly, or the one
        assignment of a name, a self or class attribute), a list parameter (`ParamList`: one element
        per item the configuration sets), or an Unknown naming what is not known."""
        if depth > 10:
            return self.unknown(expr, "too deep")
        if isinstance(expr, (ast.List, ast.Tuple, ast.Set)) and not any(isinstance(e, ast.Starred) for e in expr.elts):
            return [Element(e, scope) for e in expr.elts]
        if isinstance(expr, ast.Call) and isinstance(expr.func, ast.Name) and expr.func.id in _SAME_ELEMENTS \
                and len(expr.args) == 1:
            return self.elements(expr.args[0], scope, depth + 1)
        if isinstance(expr, ast.Call) and isinstance(expr.func, ast.Name) and expr.args and not expr.keywords and \
                (expr.func.id == "zip" or expr.func.id == "enumerate" and len(expr.args) == 1):
            columns = [self.elements(a, scope, depth + 1) for a in expr.args]
            if all(isinstance(c, list) for c in columns):
                known = [c for c in columns if isinstance(c, list)]
                if expr.func.id == "enumerate":
                    known.insert(0, [Element(ast.Constant(index), None) for index in range(len(known[0]))])
                return [Element(None, None, parts=row) for row in zip(*known)]
        if isinstance(expr, ast.Call) and self.qualified(expr.func) == "rospy.get_param" and expr.args:
            name = self.value(expr.args[0], depth + 1, scope)
            if isinstance(name, str):
                return ParamList(name, file=self.file, line=expr.lineno,
                                 defaults=self.strings(arg(expr, 1, "default"), scope, depth + 1))
        if isinstance(expr, ast.Name) and (item := self.binding(expr.id, scope)) is not None:
            return self.elements(item.expr, item.scope, depth + 1) if item.expr is not None else \
                self.unknown(expr, "elements of an element not known")
        if isinstance(expr, ast.Name) and scope is not None and expr.id not in scope.assigns and \
                expr.id in parameters(scope):
            passed = self.arguments(scope, expr.id)
            if len(passed) == 1 and passed[0][0] is not None:  # the one call site's argument
                return self.elements(passed[0][0], passed[0][1], depth + 1)
        assigned = self.assigned(expr, scope)
        if assigned is not None:
            own = [a for a in assigned[0] if not (isinstance(a, ast.expr) and _mentions(a, expr))]  # `x = [x]` wraps
            if len(own) == 1 and isinstance(own[0], ast.expr):
                return self.elements(own[0], self.attr_scope.get(id(own[0]), assigned[1]), depth + 1)
        return self.unknown(expr, "a sequence not known statically")

    def strings(self, expr: ast.expr | None, scope: Function | None, depth: int) -> tuple[str, ...] | None:
        """The elements of a sequence when all are known strings (a list parameter's default), else None."""
        items = self.elements(expr, scope, depth) if expr is not None else None
        if not isinstance(items, list):
            return None
        values = [self.value(i.expr, depth + 1, i.scope) for i in items if i.expr is not None]
        strings = [v for v in values if isinstance(v, str)]
        return tuple(strings) if len(strings) == len(items) else None

    def assigned(self, expr: ast.expr, scope: Function | None) -> tuple[list[Assigned], Function | None] | None:
        """What a name (local, else module-level) or a self or class attribute is assigned, with the
        function those values fold in; None for anything else."""
        if isinstance(expr, ast.Name):
            if scope is not None and expr.id in scope.assigns:
                return scope.assigns[expr.id], scope
            return self.module_assigns.get(expr.id, []), None
        if is_self_attr(expr) and scope is not None and scope.cls:
            return self.class_attrs.get(scope.cls, {}).get(expr.attr, []), scope
        if isinstance(expr, ast.Attribute) and isinstance(expr.value, ast.Name) and expr.value.id in self.class_attrs:
            return self.class_attrs[expr.value.id].get(expr.attr, []), None
        return None

    def unknown(self, expr: ast.expr, why: str = "") -> Unknown:
        """An expression not folded, with its file and line."""
        return Unknown(ast.unparse(expr) + (f" ({why})" if why else ""), self.file, getattr(expr, "lineno", 0))

    def value(self, expr: ast.expr | None, depth: int = 0, scope: Function | None = None) -> Value:
        """The value of an expression in a function (by default the walk's)."""
        scope = self.scope if scope is None else scope
        if expr is None:
            return Unknown("<missing argument>", self.file, 0)
        if depth > 10:
            return self.unknown(expr, "too deep")
        if isinstance(expr, ast.Constant):
            if isinstance(expr.value, str):
                return expr.value
            if isinstance(expr.value, bool):
                return str(expr.value).lower()
            if isinstance(expr.value, (int, float)):
                return str(expr.value)
            return self.unknown(expr)
        if isinstance(expr, ast.Name):
            return self.name_value(expr, depth, scope)
        if is_self_attr(expr) and scope is not None and (id(scope.node), ast.unparse(expr)) in self.current:
            return self.current[(id(scope.node), ast.unparse(expr))]
        if isinstance(expr, ast.Attribute) and (found := self.assigned(expr, scope)) is not None:
            return self.single(found[0], expr, depth, found[1])
        if isinstance(expr, ast.BinOp) and isinstance(expr.op, ast.Add):
            return concat(self.value(expr.left, depth + 1, scope), self.value(expr.right, depth + 1, scope))
        if isinstance(expr, ast.BinOp) and isinstance(expr.op, ast.Mod) and isinstance(expr.left, ast.Constant):
            return self.percent(expr, depth, scope)
        if isinstance(expr, ast.JoinedStr):
            parts = [self.value(v.value, depth + 1, scope) if isinstance(v, ast.FormattedValue)
                     and v.conversion == -1 and v.format_spec is None else
                     (str(v.value) if isinstance(v, ast.Constant) else self.unknown(expr)) for v in expr.values]
            return concat(*parts)
        if isinstance(expr, ast.Call):
            return self.call_value(expr, depth, scope)
        if isinstance(expr, ast.IfExp):
            return alternatives([self.value(expr.body, depth + 1, scope), self.value(expr.orelse, depth + 1, scope)],
                                False, self.unknown(expr, "one of several values"))
        if isinstance(expr, ast.Attribute) and isinstance(expr.value, ast.Call) and expr.attr in _PARAMETER_VALUES:
            return self.call_value(expr.value, depth + 1, scope)
        if isinstance(expr, ast.Subscript) and isinstance(expr.slice, ast.Constant) and \
                isinstance(expr.slice.value, str) and isinstance(listed := self.value(expr.value, depth + 1, scope),
                                                                 ParamList) and not listed.field and not listed.entry:
            return replace(listed, field=expr.slice.value, defaults=None)  # `item["topic"]` of a list of dicts
        return self.unknown(expr)

    def name_value(self, expr: ast.Name, depth: int, scope: Function | None) -> Value:
        """A name: a bound loop variable, a local assignment, a parameter (from its call sites), or a
        module assignment."""
        if (item := self.binding(expr.id, scope)) is not None:
            if item.expr is not None:
                return self.value(item.expr, depth + 1, item.scope)
            return item.value if item.value is not None else self.unknown(expr)
        if scope is not None:
            if (id(scope.node), expr.id) in self.current:
                return self.current[(id(scope.node), expr.id)]
            if expr.id in scope.assigns:
                return self.single(scope.assigns[expr.id], expr, depth, scope)
            if expr.id in parameters(scope):
                return self.parameter(scope, expr.id, expr, depth)
        return self.single(self.module_assigns.get(expr.id, []), expr, depth, None)

    def single(self, exprs: list[Assigned], at: ast.expr, depth: int, scope: Function | None) -> Value:
        """The value of a variable: one assignment gives its value, several (if/else) give
        alternatives, a loop over known elements gives every element (a list parameter's, each)."""
        if len(exprs) == 1 and isinstance(exprs[0], ast.For) and isinstance(exprs[0].target, ast.Name):
            items = self.elements(exprs[0].iter, scope, depth + 1)
            if not isinstance(items, list):
                return items if isinstance(items, ParamList) else self.unknown(at, "loop over values not known "
                                                                                   "statically")
            return alternatives([self.value(i.expr, depth + 1, i.scope) if i.expr is not None else self.unknown(at)
                                 for i in items], True, self.unknown(at, "loop over values not known statically"))
        if (flowed := self.in_order(exprs, at, depth, scope)) is not None:
            return flowed
        values = [self.value(e, depth + 1, self.attr_scope.get(id(e), scope)) if isinstance(e, ast.expr)
                  else self.unknown(at, _KIND[type(e)]) for e in exprs]
        if not values:
            return self.unknown(at, "not assigned in this file")
        return alternatives(values, False, self.unknown(at, "assigned values not all known"))

    def in_order(self, exprs: list[Assigned], at: ast.expr, depth: int, scope: Function | None) -> Value | None:
        """The value a local name or self attribute that one function assigns several times holds
        after that function's statements, followed in order: a parameter read in `try` whose `except
        KeyError` assigns a default, and `if` on the value itself (`if x != '': x = '/' + x`, a
        Switch decided per node instance). None when that does not apply: a use before the last
        assignment, or statements it does not follow (loops, other tests)."""
        if len(exprs) < 2 or not all(isinstance(e, ast.expr) for e in exprs) or scope is None:
            return None
        owners = {id(self.attr_scope.get(id(e))) for e in exprs} if is_self_attr(at) else {id(scope)}
        owner = self.attr_scope.get(id(exprs[0])) if is_self_attr(at) else scope
        if len(owners) != 1 or owner is None or not isinstance(at, ast.Name) and not is_self_attr(at):
            return None
        if self.function_of(at) is owner and at.lineno <= max(getattr(e, "lineno", 0) for e in exprs):
            return None
        if not _followable(owner.node.body, ast.unparse(at)):  # checked before anything is folded
            return None
        try:
            return self._flow(owner.node.body, None, owner, ast.unparse(at), depth)
        except _NotInOrder:
            return None

    def _flow(self, stmts: list[ast.stmt], state: Value | None, owner: Function, text: str, depth: int) -> Value | None:
        """The value of `text` after `stmts` (None: not assigned yet); _NotInOrder when not followed."""
        for stmt in stmts:
            if not any(_assigns(node, text) for node in ast.walk(stmt)):
                continue
            if isinstance(stmt, (ast.Assign, ast.AnnAssign)) and stmt.value is not None and \
                    all(isinstance(t, (ast.Name, ast.Attribute)) for t in _targets(stmt)):
                state = self._assigned_now(stmt.value, state, owner, text, depth)
            elif isinstance(stmt, ast.Try) and not any(_assigns(n, text) for s in stmt.finalbody for n in ast.walk(s)):
                tried = self._flow(stmt.orelse, self._flow(stmt.body, state, owner, text, depth), owner, text, depth)
                state = _caught(tried, [(h, self._flow(h.body, state, owner, text, depth)) for h in stmt.handlers])
            elif isinstance(stmt, ast.If):
                then = self._flow(stmt.body, state, owner, text, depth)
                other = self._flow(stmt.orelse, state, owner, text, depth)
                test = _equality(stmt.test, text)
                if then == other:
                    state = then
                elif test is None or state is None or then is None or other is None:
                    raise _NotInOrder
                else:
                    state = Switch(state, test[0], then if test[1] else other, other if test[1] else then)
            else:
                raise _NotInOrder
        return state

    def _assigned_now(self, expr: ast.expr, state: Value | None, owner: Function, text: str, depth: int) -> Value:
        """The value of an assignment in order: the variable in it holds its value so far."""
        key = (id(owner.node), text)
        self.current[key] = state if state is not None else self.unknown(expr, "used before it is assigned")
        try:
            return self.value(expr, depth + 1, owner)
        finally:
            del self.current[key]

    def parameter(self, scope: Function, name: str, at: ast.expr, depth: int) -> Value:
        """A parameter takes the value all call sites in the file pass (or its default)."""
        values = {self.value(passed, depth + 1, caller) if passed is not None else self.unknown(at)
                  for passed, caller in self.arguments(scope, name)}
        if len(values) == 1:
            return next(iter(values))
        return self.unknown(at, "call sites pass different values" if values else "parameter not passed in this file")


    def percent(self, expr: ast.BinOp, depth: int, scope: Function | None) -> Value:
        """`'template' % items` with %s, %d and %r."""
        template = expr.left.value if isinstance(expr.left, ast.Constant) else None
        items = expr.right.elts if isinstance(expr.right, ast.Tuple) else [expr.right]
        pieces = re.split(r"%[sdr]", template) if isinstance(template, str) else []
        if len(pieces) != len(items) + 1:
            return self.unknown(expr)
        parts: list[Value] = [pieces[0]]
        for item, piece in zip(items, pieces[1:]):
            parts += [self.value(item, depth + 1, scope), piece]
        return concat(*parts)

    def call_value(self, expr: ast.Call, depth: int, scope: Function | None) -> Value:
        """`.format()`, parameter reads (rospy and rclpy), and calls that pass a value through."""
        func = self.qualified(expr.func)
        if isinstance(expr.func, ast.Attribute) and expr.func.attr == "format" and \
                isinstance(expr.func.value, ast.Constant) and isinstance(expr.func.value.value, str):
            return self.format_value(expr, expr.func.value.value, depth, scope)
        if func == "rospy.get_param" and expr.args:
            name = self.value(expr.args[0], depth + 1, scope)
            default = arg(expr, 1, "default")
            if isinstance(name, str):
                return ParamRef(name, self.value(default, depth + 1, scope) if default is not None
                                else self.unknown(expr, "parameter without default"), "", self.file, expr.lineno)
        if func == "rospy.resolve_name" and len(expr.args) == 1:  # resolved and remapped as a handle's namespace
            return Namespace(self.value(expr.args[0], depth + 1, scope))
        if func == "rospy.get_namespace" and not expr.args:  # the node's namespace, with a final slash
            return concat(Namespace(), "/")
        if func in ("str", "os.path.join") and len(expr.args) == 1:
            return self.value(expr.args[0], depth + 1, scope)
        if isinstance(expr.func, ast.Attribute) and expr.func.attr == "get_parameter_value" and \
                isinstance(expr.func.value, ast.Call):
            return self.call_value(expr.func.value, depth + 1, scope)
        if isinstance(expr.func, ast.Attribute) and expr.func.attr in ("declare_parameter", "get_parameter",
                                                                      "get_parameter_or") and expr.args:
            name = self.value(expr.args[0], depth + 1, scope)
            default = arg(expr, 1, "value" if expr.func.attr == "declare_parameter" else "alternative_value")
            if isinstance(name, str):
                default = default if default is not None and expr.func.attr != "get_parameter" else \
                    self.declared.get(name)
                return ParamRef(name, self.value(default, depth + 1, scope) if default is not None
                                else self.unknown(expr, "parameter without default"), "~", self.file, expr.lineno)
        return self.unknown(expr)

    def format_value(self, expr: ast.Call, template: str, depth: int, scope: Function | None) -> Value:
        """`template.format(...)` with its positional and keyword arguments."""
        parts: list[Value] = []
        position = 0
        for index, match in enumerate(re.finditer(r"\{(\w*)\}", template)):
            parts.append(template[position:match.start()])
            key = match.group(1)
            if key.isdigit() or not key:
                slot = int(key) if key else index
                item = expr.args[slot] if slot < len(expr.args) else None
            else:
                item = next((kw.value for kw in expr.keywords if kw.arg == key), None)
            parts.append(self.value(item, depth + 1, scope) if item is not None else self.unknown(expr))
            position = match.end()
        parts.append(template[position:])
        return concat(*parts)


def _targets(stmt: ast.Assign | ast.AnnAssign) -> list[ast.expr]:
    return stmt.targets if isinstance(stmt, ast.Assign) else [stmt.target]


def _assigns(node: ast.AST, text: str) -> bool:
    """Whether a node assigns the variable spelt `text` (as a target, or a part of one)."""
    if isinstance(node, (ast.Assign, ast.AnnAssign)):
        targets = _targets(node)
    elif isinstance(node, (ast.AugAssign, ast.For, ast.AsyncFor)):
        targets = [node.target]
    elif isinstance(node, (ast.With, ast.AsyncWith)):
        targets = [i.optional_vars for i in node.items if i.optional_vars is not None]
    else:
        return False
    return any(ast.unparse(part) == text for target in targets for part in ast.walk(target))


def _followable(stmts: list[ast.stmt], text: str) -> bool:
    """Whether the statements assigning the variable spelt `text` are only ones in_order() follows:
    plain assignments, try/except for a missing parameter, and `if` tests of the variable itself."""
    for stmt in stmts:
        if not any(_assigns(node, text) for node in ast.walk(stmt)):
            continue
        if isinstance(stmt, (ast.Assign, ast.AnnAssign)):
            if stmt.value is None or not all(isinstance(t, (ast.Name, ast.Attribute)) for t in _targets(stmt)):
                return False
        elif isinstance(stmt, ast.Try):
            if not (_followable(stmt.body, text) and _followable(stmt.orelse, text) and
                    all(_catches_missing(h) and _followable(h.body, text) for h in stmt.handlers) and
                    not any(_assigns(n, text) for s in stmt.finalbody for n in ast.walk(s))):
                return False
        elif not (isinstance(stmt, ast.If) and _equality(stmt.test, text) is not None and
                  _followable(stmt.body, text) and _followable(stmt.orelse, text)):
            return False
    return True


def _equality(test: ast.expr, text: str) -> tuple[str, bool] | None:
    """A test of the variable spelt `text` against a string: (the string, whether the test holds when
    they are equal). `if x:` is `x != ''`, `if not x:` is `x == ''`."""
    if ast.unparse(test) == text:
        return "", False
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not) and ast.unparse(test.operand) == text:
        return "", True
    if isinstance(test, ast.Compare) and len(test.ops) == 1 and isinstance(test.ops[0], (ast.Eq, ast.NotEq)):
        sides = [test.left, test.comparators[0]]
        literal = [s.value for s in sides if isinstance(s, ast.Constant) and isinstance(s.value, str)]
        if literal and any(ast.unparse(s) == text for s in sides):
            return literal[0], isinstance(test.ops[0], ast.Eq)
    return None


def _caught(tried: Value | None, caught: list[tuple[ast.ExceptHandler, Value | None]]) -> Value | None:
    """The value after try/except: a parameter read without default whose handlers for a missing
    parameter all assign one value reads with that value as its default."""
    if all(value == tried for _h, value in caught):
        return tried
    values = {value for _h, value in caught if value is not None}
    if isinstance(tried, ParamRef) and isinstance(tried.default, Unknown) and len(values) == len(caught) == 1 and \
            all(_catches_missing(h) for h, _v in caught):
        return replace(tried, default=values.pop())
    raise _NotInOrder


def _catches_missing(handler: ast.ExceptHandler) -> bool:
    """An except clause that catches the KeyError of a parameter not set."""
    kinds = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
    return any(k is None or isinstance(k, ast.Name) and k.id in _MISSING_PARAMETER for k in kinds)


def parameters(scope: Function) -> list[str]:
    """The names of a function's parameters (positional and keyword-only; a method's self too)."""
    return [a.arg for a in scope.node.args.args + scope.node.args.kwonlyargs]


def _mentions(expr: ast.expr, name: ast.expr) -> bool:
    """Whether an expression uses a name (or attribute) itself: `x = [x]` rewraps the same value."""
    text = ast.unparse(name)
    return any(isinstance(n, (ast.Name, ast.Attribute)) and ast.unparse(n) == text for n in ast.walk(expr))
