"""roslaunch substitution args: $(arg) $(find) $(env) $(optenv) $(anon) $(dirname) $(eval).

`$(eval)` is interpreted over Python's AST with roslaunch's restricted names only; nothing from
the project is ever executed.
"""

from __future__ import annotations

import ast
import operator
import os
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path


class SubstitutionError(Exception):
    """A substitution roslaunch would reject or that cannot be resolved statically."""


@dataclass
class SubstContext:
    """What substitutions can see: the current file's args, package lookup and environment."""

    args: dict[str, str]
    find: Callable[[str], Path | None]
    file: Path
    anon: dict[str, str] = field(default_factory=dict)
    env: dict[str, str] = field(default_factory=lambda: dict(os.environ))
    args_declared: set[str] = field(default_factory=set)

    def arg(self, name: str) -> str:
        if name not in self.args:
            raise SubstitutionError(f"arg '{name}' is not defined")
        return self.args[name]

    def find_pkg(self, name: str) -> str:
        path = self.find(name)
        if path is None:
            raise SubstitutionError(f"package '{name}' not found")
        return str(path)

    def getenv(self, name: str, default: str | None = None) -> str:
        if name in self.env:
            return self.env[name]
        if default is None:
            raise SubstitutionError(f"environment variable '{name}' is not set")
        return default

    def anonymous(self, name: str) -> str:
        return self.anon.setdefault(name, f"{name}_anon{len(self.anon) + 1}")


_CALL = re.compile(r"\$\((\w+)((?:\s[^$()]*)?)\)")


def substitute(text: str, ctx: SubstContext) -> str:
    """Resolve every substitution in `text`, innermost first."""
    stripped = text.strip()
    if stripped.startswith("$(eval ") and stripped.endswith(")"):
        return _eval(stripped[7:-1], ctx)
    previous = None
    while previous != text and "$(" in text:
        previous = text
        text = _CALL.sub(lambda m: _one(m.group(1), m.group(2).split(), ctx), text, count=1)
    if "$(" in text:
        raise SubstitutionError(f"cannot resolve '{text}'")
    return text


def _one(command: str, words: list[str], ctx: SubstContext) -> str:
    if command == "arg" and len(words) == 1:
        return ctx.arg(words[0])
    if command == "find" and len(words) == 1:
        return ctx.find_pkg(words[0])
    if command == "env" and len(words) == 1:
        return ctx.getenv(words[0])
    if command == "optenv" and words:
        return ctx.getenv(words[0], " ".join(words[1:]))
    if command == "anon" and len(words) == 1:
        return ctx.anonymous(words[0])
    if command == "dirname" and not words:
        return str(ctx.file.parent)
    raise SubstitutionError(f"unknown or malformed substitution $({command} {' '.join(words)})")


# -- restricted $(eval) -------------------------------------------------------------------
_BINOPS = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Pow: operator.pow,
}
_CMPOPS = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b,
}
_STR_METHODS = {"lower", "upper", "strip", "startswith", "endswith", "replace", "split", "join", "format"}


def _eval(expr: str, ctx: SubstContext) -> str:
    try:
        tree = ast.parse(expr.strip(), mode="eval")
    except SyntaxError as exc:
        raise SubstitutionError(f"$(eval) syntax error: {exc.msg}") from None
    functions: dict[str, Callable[..., object]] = {
        "arg": ctx.arg, "find": ctx.find_pkg, "env": ctx.getenv,
        "optenv": lambda n, d="": ctx.getenv(n, d), "anon": ctx.anonymous,
        "dirname": lambda: str(ctx.file.parent),
        **{f.__name__: f for f in (int, float, str, bool, len, abs, min, max, round)},
    }
    return str(_Evaluator(ctx, functions).visit(tree.body))


class _Evaluator(ast.NodeVisitor):
    def __init__(self, ctx: SubstContext, functions: dict[str, Callable[..., object]]) -> None:
        self.ctx, self.functions = ctx, functions

    def generic_visit(self, node: ast.AST) -> object:
        raise SubstitutionError(f"$(eval) does not allow {type(node).__name__}")

    def visit_Constant(self, node: ast.Constant) -> object:
        return node.value

    def visit_Name(self, node: ast.Name) -> object:
        names = {"true": True, "false": False, "True": True, "False": False, "None": None}
        return names[node.id] if node.id in names else self.ctx.arg(node.id)

    def visit_List(self, node: ast.List) -> object:
        return [self.visit(e) for e in node.elts]

    def visit_Tuple(self, node: ast.Tuple) -> object:
        return tuple(self.visit(e) for e in node.elts)

    def visit_BoolOp(self, node: ast.BoolOp) -> object:
        result: object = isinstance(node.op, ast.And)
        for value in node.values:
            result = self.visit(value)
            if bool(result) != isinstance(node.op, ast.And):
                return result
        return result

    def visit_UnaryOp(self, node: ast.UnaryOp) -> object:
        value = self.visit(node.operand)
        ops = {ast.Not: operator.not_, ast.USub: operator.neg, ast.UAdd: operator.pos}
        if type(node.op) not in ops:
            return self.generic_visit(node)
        return ops[type(node.op)](value)

    def visit_BinOp(self, node: ast.BinOp) -> object:
        if type(node.op) not in _BINOPS:
            return self.generic_visit(node)
        left, right = self.visit(node.left), self.visit(node.right)
        if isinstance(node.op, ast.Pow) and isinstance(right, (int, float)) and abs(right) > 64:
            raise SubstitutionError("$(eval) exponent too large")
        if isinstance(node.op, ast.Mult) and any(isinstance(v, (str, list)) for v in (left, right)):
            count = right if isinstance(right, int) else left
            if isinstance(count, int) and count > 10_000:
                raise SubstitutionError("$(eval) repetition too large")
        try:
            return _BINOPS[type(node.op)](left, right)
        except (TypeError, ZeroDivisionError, ValueError) as exc:
            raise SubstitutionError(f"$(eval) {exc}") from None

    def visit_Compare(self, node: ast.Compare) -> object:
        left = self.visit(node.left)
        for op, comparator in zip(node.ops, node.comparators):
            right = self.visit(comparator)
            if type(op) not in _CMPOPS:
                return self.generic_visit(node)
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
        if node.keywords:
            return self.generic_visit(node)
        args = [self.visit(a) for a in node.args]
        if isinstance(node.func, ast.Name) and node.func.id in self.functions:
            return self.functions[node.func.id](*args)
        if isinstance(node.func, ast.Attribute) and node.func.attr in _STR_METHODS:
            target = self.visit(node.func.value)
            if isinstance(target, str):
                return getattr(target, node.func.attr)(*args)
        raise SubstitutionError(f"$(eval) cannot call {ast.unparse(node.func)}")
