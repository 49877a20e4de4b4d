"""The restricted expression evaluator shared by roslaunch's $(eval), ROS 2's PythonExpression
and Python launch files, and xacro's ${...}: pure expressions over Python's AST, nothing from the
project ever executed. Evaluation spends from the budget (archlog.budget): characters for what
operations are about to build (checked before building), a step per evaluated node, and the
nesting depth of an expression.
"""

from __future__ import annotations

import ast
import math
import operator
import re
import sys
from collections.abc import Callable
from typing import Any

from archlog import budget
from archlog.extract.launch.model import SubstitutionError

_BINOPS = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Pow: operator.pow,
}
_CMPOPS = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b,
    ast.Is: operator.is_, ast.IsNot: operator.is_not,
}
STR_METHODS = {"lower", "upper", "strip", "lstrip", "rstrip", "startswith", "endswith", "replace", "split",
                "join", "find", "count", "capitalize", "title", "isdigit", "format"}
MATH = {k: v for k, v in vars(math).items() if not k.startswith("_")}
INT_DIGITS = sys.get_int_max_str_digits() or 4300
"""Longest integer an expression may build (Python's own limit for printing one)."""


def _sum(values: object, start: object = 0) -> object:
    """sum(), concatenating lists in linear time (the builtin copies the whole prefix each step)."""
    items = list(values)  # type: ignore[call-overload]
    if isinstance(start, list) and all(isinstance(item, list) for item in items):
        joined = list(start)
        for item in items:
            joined.extend(item)
            bounded(joined)
        return joined
    return sum(items, start)  # type: ignore[call-overload]


def _range(*bounds: int) -> range:
    """range() whose length is spent as evaluation steps (each element may be visited)."""
    numbers = range(*bounds)
    try:
        spend("steps", len(numbers))
    except OverflowError:  # longer than sys.maxsize
        spend("steps", sys.maxsize)
    return numbers


BUILTINS = {f.__name__: f for f in (int, float, str, bool, list, dict, tuple, len, abs, min, max, round, sorted,
                                    map, filter, zip, any, all, reversed, enumerate, chr, ord, hex, oct, bin,
                                    divmod, repr, isinstance)} | {"sum": _sum}
PURE_BUILTINS = {**BUILTINS, "range": _range, "set": set, "frozenset": frozenset}
"""The builtins above, with range() and sets (for languages whose expressions offer them)."""
_NUMBER = re.compile(r"\d+")
_NESTED_FIELD = re.compile(r"\{[^{}]*\{")
_FIELD_ATTRIBUTE = re.compile(r"\{[^{}:!]*\.")  # {0.attr}: str.format reading an attribute
_SEQUENCES = (str, bytes, list, tuple)
_HUGE = 2 ** 62  # more characters than any budget allows


def restricted_eval(expr: str, lookup: Callable[[str], object],
                    attribute: Callable[[object, str], object] | None = None) -> object:
    """Evaluate a Python expression over the AST whitelist of `Evaluator`; names come from `lookup`,
    `a.b` (when allowed) from `attribute`."""
    if "__" in expr:
        raise SubstitutionError("$(eval ...) may not contain double underscore expressions")
    try:
        tree = parse(expr.strip(), "<eval>", "eval")
    except (SyntaxError, ValueError) as exc:  # ValueError: a NUL byte
        raise SubstitutionError(f"$(eval) syntax error: {getattr(exc, 'msg', exc)}") from None
    assert isinstance(tree, ast.Expression)
    return Evaluator(lookup, attribute).visit(tree.body)


spend = budget.spend


def bounded(value: object) -> object:
    """`value` if its text stays within the characters budget (raises `BudgetExceeded`) and an
    integer within `INT_DIGITS` (raises `SubstitutionError`, as Python could not print it)."""
    if isinstance(value, int) and _digits(value) > INT_DIGITS:
        raise SubstitutionError(f"$(eval) integer of more than {INT_DIGITS} digits")
    budget.current().check("characters", size(value))
    return value


def size(value: object, memo: dict[int, int] | None = None, depth: int = 0) -> int:
    """About how many characters `str(value)` has, a part shared several times counted each time
    (each container is walked once; every entry walked spends an evaluation step)."""
    if isinstance(value, str):
        return len(value)
    if isinstance(value, int):
        return _digits(value)
    if not isinstance(value, (list, tuple, dict, set, frozenset)):
        return 24
    memo = {} if memo is None else memo
    if id(value) not in memo:
        if depth > budget.current().limits["depth"]:
            budget.current().check("depth", depth)
        spend("steps", len(value))
        items = [*value.keys(), *value.values()] if isinstance(value, dict) else value
        memo[id(value)] = 2 + sum(size(item, memo, depth + 1) + 2 for item in items)
    return memo[id(value)]


class TooDeep(budget.BudgetExceeded):
    """Source nested past the depth limit (at `line`)."""

    def __init__(self, limit: int, line: int) -> None:
        super().__init__("depth", limit)
        self.line = line


def parse(source: str, filename: str, mode: str = "exec") -> ast.AST:
    """`ast.parse` within the depth budget: a source too deeply nested for the parser, or whose
    tree is deeper than the limit, raises TooDeep (SyntaxError passes through)."""
    limit = budget.current().limits["depth"]
    try:
        tree = ast.parse(source, filename, mode)
    except (RecursionError, MemoryError):
        raise TooDeep(limit, 1) from None
    depth, line = tree_depth(tree)
    if depth > limit:
        raise TooDeep(limit, line)
    return tree


def tree_depth(tree: ast.AST) -> tuple[int, int]:
    """How deeply a syntax tree nests, and the line where it is deepest (measured without recursion)."""
    deepest, stack = (0, 1), [(tree, 1, 1)]
    while stack:
        node, depth, line = stack.pop()
        line = getattr(node, "lineno", line)
        deepest = max(deepest, (depth, line), key=lambda d: d[0])
        stack.extend((child, depth + 1, line) for child in ast.iter_child_nodes(node))
    return deepest


def result_size(op: ast.operator, left: object, right: object) -> int:
    """How many characters (digits, items) `left op right` is about to build: what it costs."""
    if isinstance(op, ast.Mult):
        for seq, count in ((left, right), (right, left)):
            if isinstance(seq, _SEQUENCES) and isinstance(count, int):
                return len(seq) * max(count, 0)
        if isinstance(left, int) and isinstance(right, int):
            return _digits(left) + _digits(right)
    if isinstance(op, ast.Add) and isinstance(left, _SEQUENCES) and isinstance(right, _SEQUENCES):
        return len(left) + len(right)
    if isinstance(op, ast.Pow) and isinstance(left, int) and isinstance(right, int) and right > 0 and abs(left) > 1:
        return _times(right, math.log10(abs(left)))
    if isinstance(op, ast.Mod) and isinstance(left, str):
        return format_size(left, right if isinstance(right, tuple) else (right,), "*" in left)
    return 0


def call_size(function: object, args: list[object], kwargs: dict[str, object]) -> int:
    """How many characters (digits) a call of a pure function or str method is about to build."""
    owner, name = getattr(function, "__self__", None), getattr(function, "__name__", "")
    if isinstance(owner, str) and name == "format":
        return format_size(owner, [*args, *kwargs.values()], bool(_NESTED_FIELD.search(owner)))
    if isinstance(owner, str) and name == "join" and args and isinstance(args[0], (list, tuple)):
        return sum(len(a) for a in args[0] if isinstance(a, str)) + len(owner) * len(args[0])
    if isinstance(owner, str) and name == "replace" and len(args) >= 2 and all(isinstance(a, str) for a in args[:2]):
        old, new = args[0], args[1]
        return len(owner) + (owner.count(old) if old else len(owner) + 1) * len(new)  # type: ignore[arg-type]
    if function in (str, repr):
        return sum(text_size(a) for a in args)
    numbers = [a for a in args if isinstance(a, int)]
    if function is math.factorial and numbers and numbers[0] > 1:
        return _times(numbers[0], math.log10(numbers[0]))  # n! < n**n
    if function is round and len(numbers) == 2 and numbers[1] < 0:  # computes 10 ** -ndigits
        return -numbers[1]
    if function in (math.comb, math.perm) and len(numbers) == 2 and numbers[0] > 1:
        return _times(min(numbers[0], abs(numbers[1])), math.log10(numbers[0]))
    if function in (math.prod, math.lcm, sum):
        items = args[0] if function is not math.lcm and args and isinstance(args[0], (list, tuple)) else args
        return sum(_digits(i) if isinstance(i, int) else len(i) if isinstance(i, _SEQUENCES) else 0
                   for i in [*items, *args[1:]])
    return 0


def format_size(template: str, args: tuple[object, ...] | list[object], widths_in_args: bool) -> int:
    """An upper bound of what formatting `args` into `template` builds: the template, the arguments,
    every number written in the template (a width or precision) and, when the template takes
    widths from the arguments (`*`, a nested field), every integer argument."""
    size = len(template) + sum(int(n) if len(n) < 19 else 10 ** 19 for n in _NUMBER.findall(template))
    for arg in args:
        if isinstance(arg, int) and not isinstance(arg, bool) and widths_in_args:
            size += min(abs(arg), 10 ** 19)
        else:
            size += text_size(arg)
    return size


def text_size(value: object) -> int:
    """About how many characters str() of a value writes: a part shared by several containers (a
    list repeated into itself) is written out each time it appears, so it counts each time."""
    sizes: dict[int, int] = {}

    def size(item: object) -> int:
        if isinstance(item, (str, bytes)):
            return len(item) + 3
        if isinstance(item, int):
            return _digits(item)
        if not isinstance(item, (list, tuple, dict, set, frozenset)):
            return 24
        if id(item) not in sizes:
            parts = [p for pair in item.items() for p in pair] if isinstance(item, dict) else list(item)
            sizes[id(item)] = 2 + sum(size(p) + 2 for p in parts)
        return sizes[id(item)]

    return size(value)


def _times(count: int, digits: float) -> int:
    """`count` times `digits`, rounded up (a count too large for a float stands for "too many")."""
    return math.ceil(count * digits) if count < _HUGE else _HUGE


def _digits(number: int) -> int:
    return abs(number).bit_length() * 3 // 10 + 1


def arithmetic(expr: str) -> object:
    """A plain arithmetic expression over numbers, pi and the math functions (for rosparam's rad())."""
    def lookup(name: str) -> object:
        if name not in MATH:
            raise SubstitutionError(f"name '{name}' is not defined")
        return MATH[name]

    return restricted_eval(expr, lookup)


class Evaluator(ast.NodeVisitor):
    """Evaluates pure expressions: no calls but to what `lookup` gives and the str methods of
    `STR_METHODS`, no attribute access but through `attribute` (when given; never a name starting
    with `_`). Every node spends an evaluation step, and every value built is `bounded`."""

    def __init__(self, lookup: Callable[[str], object],
                 attribute: Callable[[object, str], object] | None = None) -> None:
        self.lookup = lookup
        self.attribute = attribute

    def visit(self, node: ast.AST) -> object:
        budget.spend("steps")
        return super().visit(node)

    def generic_visit(self, node: ast.AST) -> object:
        raise SubstitutionError(f"$(eval) does not allow {type(node).__name__}")

    def visit_Constant(self, node: ast.Constant) -> object:
        return node.value

    def visit_Name(self, node: ast.Name) -> object:
        return self.lookup(node.id)

    def visit_Attribute(self, node: ast.Attribute) -> object:
        if self.attribute is None or node.attr.startswith("_"):
            return self.generic_visit(node)
        return self.attribute(self.visit(node.value), node.attr)

    def visit_Dict(self, node: ast.Dict) -> object:
        if any(k is None for k in node.keys):
            return self.generic_visit(node)
        return bounded({self.visit(k): self.visit(v) for k, v in zip(node.keys, node.values)})  # type: ignore[arg-type]

    def visit_Slice(self, node: ast.Slice) -> object:
        return slice(*(None if part is None else self.visit(part) for part in (node.lower, node.upper, node.step)))

    def visit_JoinedStr(self, node: ast.JoinedStr) -> object:
        pieces = [str(self.visit(value)) for value in node.values]
        budget.charge("characters", sum(len(p) for p in pieces))
        return "".join(pieces)

    def visit_FormattedValue(self, node: ast.FormattedValue) -> object:
        value = self.visit(node.value)
        spec = str(self.visit(node.format_spec)) if node.format_spec is not None else ""
        budget.charge("characters", format_size(spec, (value,), False))  # before it is written out
        conversions: dict[int, Callable[[object], object]] = {ord("s"): str, ord("r"): repr, ord("a"): ascii}
        convert = conversions.get(node.conversion, lambda v: v)
        try:
            return format(convert(value), spec)
        except (TypeError, ValueError) as exc:
            raise SubstitutionError(f"$(eval) {exc}") from None

    def visit_List(self, node: ast.List) -> object:
        return bounded([self.visit(e) for e in node.elts])

    def visit_Tuple(self, node: ast.Tuple) -> object:
        return bounded(tuple(self.visit(e) for e in node.elts))

    def visit_Subscript(self, node: ast.Subscript) -> object:
        target, index = self.visit(node.value), self.visit(node.slice)
        try:
            return target[index]  # type: ignore[index]
        except (TypeError, KeyError, IndexError, AttributeError) as exc:
            raise SubstitutionError(f"$(eval) {exc}") from None

    def visit_BoolOp(self, node: ast.BoolOp) -> object:
        result: object = isinstance(node.op, ast.And)
        for value in node.values:
            result = self.visit(value)
            if bool(result) != isinstance(node.op, ast.And):
                return result
        return result

    def visit_UnaryOp(self, node: ast.UnaryOp) -> object:
        ops: dict[type[ast.unaryop], Callable[[Any], object]] = {
            ast.Not: operator.not_, ast.USub: operator.neg, ast.UAdd: operator.pos}
        if type(node.op) not in ops:
            return self.generic_visit(node)
        try:
            return ops[type(node.op)](self.visit(node.operand))
        except TypeError as exc:
            raise SubstitutionError(f"$(eval) {exc}") from None

    def visit_BinOp(self, node: ast.BinOp) -> object:
        if type(node.op) not in _BINOPS:
            return self.generic_visit(node)
        left, right = self.visit(node.left), self.visit(node.right)
        budget.charge("characters", result_size(node.op, left, right))
        try:
            return bounded(_BINOPS[type(node.op)](left, right))
        except (TypeError, ZeroDivisionError, ValueError, OverflowError) as exc:
            raise SubstitutionError(f"$(eval) {exc}") from None

    def visit_Compare(self, node: ast.Compare) -> object:
        left = self.visit(node.left)
        for op, comparator in zip(node.ops, node.comparators):
            right = self.visit(comparator)
            try:
                if not _CMPOPS[type(op)](left, right):
                    return False
            except TypeError as exc:
                raise SubstitutionError(f"$(eval) {exc}") from None
            left = right
        return True

    def visit_IfExp(self, node: ast.IfExp) -> object:
        return self.visit(node.body) if self.visit(node.test) else self.visit(node.orelse)

    def visit_Call(self, node: ast.Call) -> object:
        if any(k.arg is None for k in node.keywords) or any(isinstance(a, ast.Starred) for a in node.args):
            return self.generic_visit(node)
        function = self.callee(node.func)
        args = [self.visit(a) for a in node.args]
        kwargs = {k.arg: self.visit(k.value) for k in node.keywords if k.arg is not None}
        owner = getattr(function, "__self__", None)
        if isinstance(owner, str) and getattr(function, "__name__", "") == "format" and \
                ("__" in owner or _FIELD_ATTRIBUTE.search(owner)):
            raise SubstitutionError("$(eval) format string not allowed (it reads attributes)")
        budget.charge("characters", call_size(function, args, kwargs))
        try:
            return bounded(function(*args, **kwargs))
        except (TypeError, ValueError, OverflowError, LookupError, AttributeError) as exc:
            raise SubstitutionError(f"$(eval) {exc}") from None

    def callee(self, func: ast.expr) -> Callable[..., object]:
        """What a call calls: a name, a str method, or (with `attribute`) a name's attribute."""
        if isinstance(func, ast.Name):
            function = self.lookup(func.id)
        elif isinstance(func, ast.Attribute) and not func.attr.startswith("_"):
            target = self.visit(func.value)
            if isinstance(target, str) and func.attr in STR_METHODS:
                function = getattr(target, func.attr)
            elif self.attribute is not None and not isinstance(target, str):
                function = self.attribute(target, func.attr)
            else:
                raise SubstitutionError(f"$(eval) cannot call {func.attr} on {type(target).__name__}")
        else:
            raise SubstitutionError(f"$(eval) cannot call {ast.unparse(func)}")
        if not callable(function):
            raise SubstitutionError(f"$(eval) {ast.unparse(func)} is not callable")
        return function

