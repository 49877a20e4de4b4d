"""One budget for everything that expands: launch elements and includes, node instances, characters of expanded
strings, evaluation steps, alternatives of a value. Each unit of input (a launch configuration, a
source file, a parameter file, a robot description) spends from a fresh `scope()`; crossing a limit
raises `BudgetExceeded`, which the reader turns into a `budget-exceeded` diagnostic at the place
that crossed it, keeping what it had read so far, and the run goes on with the rest.

Limits come from `[budget]` in archlog.toml (keys as in `LIMITS`); `analyse()` installs them with
`active()`.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field

LIMITS = {
    "elements": 200_000,      # launch/xacro/YAML elements produced by one unit (after includes, macros)
    "nodes": 25_000,          # node instances one launch configuration starts
    "characters": 20_000_000, # characters of strings built by expansion in one unit
    "steps": 2_000_000,       # evaluation steps ($(eval), xacro ${}, Python launch files, C++ walks)
    "alternatives": 4_096,    # alternative values one expression may stand for
    "depth": 64,              # nesting: includes, macro calls, YAML/Python nesting
}
"""Default limits per unit of input; each is documented in docs/security.md."""


class BudgetExceeded(Exception):
    """A unit of input tried to expand past a limit."""

    def __init__(self, kind: str, limit: int) -> None:
        super().__init__(f"expansion budget exceeded: more than {limit} {kind} "
                         f"(raise [budget] {kind} in archlog.toml to allow more)")
        self.kind, self.limit = kind, limit


@dataclass
class Budget:
    limits: Mapping[str, int] = field(default_factory=lambda: dict(LIMITS))
    used: Counter[str] = field(default_factory=Counter)

    def spend(self, kind: str, amount: int = 1) -> None:
        """Count `amount` of `kind`; raises `BudgetExceeded` past its limit."""
        self.used[kind] += amount
        if self.used[kind] > self.limits[kind]:
            raise BudgetExceeded(kind, self.limits[kind])

    def charge(self, kind: str, amount: int) -> None:
        """Spend `amount` of `kind` on something about to be built; when it would not fit, it is
        refused (BudgetExceeded) without spending, so the unit can go on without it."""
        self.check(kind, self.used[kind] + amount)
        self.spend(kind, amount)

    def check(self, kind: str, value: int) -> None:
        """A measure that is not cumulative (a depth, a size about to be built) against its limit."""
        if value > self.limits[kind]:
            raise BudgetExceeded(kind, self.limits[kind])


_limits: ContextVar[Mapping[str, int]] = ContextVar("archlog_limits", default=LIMITS)
_budget: ContextVar[Budget | None] = ContextVar("archlog_budget", default=None)


@contextmanager
def active(limits: Mapping[str, int]) -> Iterator[None]:
    """Use these limits (merged over the defaults) for the run."""
    token = _limits.set({**LIMITS, **limits})
    try:
        yield
    finally:
        _limits.reset(token)


@contextmanager
def scope() -> Iterator[Budget]:
    """A fresh budget for one unit of input; nested scopes share the outer one."""
    outer = _budget.get()
    if outer is not None:
        yield outer
        return
    budget = Budget(_limits.get())
    token = _budget.set(budget)
    try:
        yield budget
    finally:
        _budget.reset(token)


def current() -> Budget:
    """The budget of the unit being read (a fresh one when no scope is open)."""
    return _budget.get() or Budget(_limits.get())


def spend(kind: str, amount: int = 1) -> None:
    current().spend(kind, amount)



def charge(kind: str, amount: int) -> None:
    current().charge(kind, amount)


class Crossed(Exception):
    """A limit crossed at file:line. `final` when a count was spent past its limit (or an expansion
    ran out of stack or memory): that ends the unit of input being read, whose reader reports it
    once, keeping what it read before; otherwise (a nesting or a build refused before it happened)
    only what crossed is skipped, reported by the nearest reader of elements."""

    def __init__(self, file: str, line: int, exceeded: BudgetExceeded, final: bool) -> None:
        super().__init__(f"{file}:{line}: {exceeded}")
        self.file, self.line, self.exceeded, self.final = file, line, exceeded, final


def crossed(file: str, line: int, error: BudgetExceeded | RecursionError | MemoryError) -> Crossed:
    """The crossing at file:line for a BudgetExceeded or, as a last resort, for the RecursionError or
    MemoryError of an expansion no limit stopped earlier."""
    if isinstance(error, BudgetExceeded):
        return Crossed(file, line, error, exhausted())
    kind = "depth" if isinstance(error, RecursionError) else "characters"
    return Crossed(file, line, BudgetExceeded(kind, current().limits[kind]), True)


def exhausted() -> bool:
    """Whether the current unit has spent a count past its limit (every further spend fails)."""
    budget = current()
    return any(budget.used[kind] > limit for kind, limit in budget.limits.items())
