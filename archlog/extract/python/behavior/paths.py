"""Paths through a file's functions: the frame a function runs in, the functions a call may
run, and the path state (trigger, guards, loop) carried along."""

from __future__ import annotations

import ast
from dataclasses import dataclass, replace

from archlog.extract.summary import Guard, Site
from archlog.values import Value

FunctionNode = ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda


@dataclass(frozen=True)
class Frame:
    """A function as it runs on one path: the arguments bound at its call, the enclosing
    function (closures) and the class of `self`. `func` None is module level."""

    func: FunctionNode | None
    cls: str | None = None
    args: tuple[tuple[str, ast.expr, Frame], ...] = ()
    outer: Frame | None = None
    called: bool = False  # reached through a call: unbound parameters take their defaults

    def __hash__(self) -> int:  # frames nest: hash once
        if "_hash" not in self.__dict__:
            object.__setattr__(self, "_hash", hash((self.func, self.cls, self.args, self.outer, self.called)))
        return self.__dict__["_hash"]

    def bound(self, name: str) -> tuple[ast.expr, Frame] | None:
        """The expression bound to a parameter at the call, with the caller's frame."""
        return next(((e, f) for n, e, f in self.args if n == name), None)


@dataclass(frozen=True)
class Target:
    """A function a call or a callback registration may run."""

    func: FunctionNode
    cls: str | None
    outer: Frame | None
    method: bool = False  # reached through an instance: its first parameter is self
    preset: tuple[tuple[ast.expr, Frame], ...] = ()  # functools.partial's arguments


@dataclass(frozen=True)
class Context:
    """A path: how it started (trigger and source port), the guards so far, the period of the
    innermost unbounded loop (a 1-tuple inside one) and the functions on it."""

    trigger: str
    source: Site | None
    guards: tuple[Guard, ...] = ()
    loop: tuple[Value] | None = None
    stack: tuple[int, ...] = ()
    opaque: frozenset[int] = frozenset()  # the statements whose unmodelled outcome the path depends on

    def guarded(self, guards: list[Guard]) -> Context:
        """The path with further guards (those not on it yet)."""
        known = {(g.var, g.value) for g in self.guards}
        new = {(g.var, g.value): g for g in guards if (g.var, g.value) not in known}
        return replace(self, guards=self.guards + tuple(new.values())) if new else self

    def depending(self, statement: ast.AST, exact: bool = False) -> Context:
        """The path past a branch of `statement` whose outcome the guards do not (or, `exact`, do) model."""
        return self if exact else replace(self, opaque=self.opaque | {id(statement)})

    def keeping(self, others: list[Context]) -> Context:
        """After branches that join again: the guards every branch has."""
        common = set.intersection(*({(g.var, g.value) for g in c.guards} for c in others))
        return replace(self, guards=tuple(g for g in others[0].guards if (g.var, g.value) in common),
                       opaque=frozenset().union(*(c.opaque for c in others)))


def join(before: Context, ends: list[Context], statement: ast.AST | None = None, alternatives: int = 0) -> Context | None:
    """The path state where branches meet (None when none of them reaches it). When all
    `alternatives` branches of `statement` reach it, it no longer depends on which one ran."""
    if not ends:
        return None
    after = ends[0] if len(ends) == 1 else before.keeping(ends)
    return replace(after, opaque=after.opaque - {id(statement)}) if len(ends) == alternatives else after

