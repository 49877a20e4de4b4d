"""Conditions a launch file leaves undecided, kept symbolically.

An `if`/`unless` (or a ROS 2 condition) that reads a launch argument whose value is not known is
not decided, and its element is kept as conditional. When the condition depends on that one
argument alone, it is kept as a `Guard`: the condition can be evaluated again with the argument
given a value (a *trial*). `settle` then asks every guard on one argument about the same values
(the words and quoted strings the conditions on it are written with, the booleans, and one value
none of them names), so two nodes whose conditions hold for no common value are known not to run
together (`if="$(eval model == 'a')"` and `'b'`; `if="$(arg x)"` and `unless="$(arg x)"`).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field

from archlog import budget
from archlog.extract.launch.model import LaunchError, LaunchNode, SubstitutionError, UnknownArg, Unresolved

OTHER = "(any other value)"  # the value no condition names
_MAX_VALUES = 64  # values tried per argument
_MAX_TRIALS = 20000  # conditions evaluated again per configuration; the nodes past it stay unsettled
_WORDS = (re.compile(r"'([^']*)'"), re.compile(r'"([^"]*)"'), re.compile(r"([\w.\-/]+)"))


@dataclass
class _Trial:
    """Values given to unknown arguments (by identity) while a condition is evaluated again, and
    the unknown arguments it read that were given none."""

    values: dict[int, str]
    read: list[tuple[str, UnknownArg]] = field(default_factory=list)


_TRIAL: ContextVar[_Trial | None] = ContextVar("archlog_launch_trial", default=None)


def given(name: str, arg: UnknownArg) -> str | None:
    """The value a trial gives the unknown argument `name` (None outside a trial, or when the trial
    gives it none: then the read is recorded)."""
    trial = _TRIAL.get()
    if trial is None:
        return None
    if id(arg) in trial.values:
        return trial.values[id(arg)]
    if all(known is not arg for _, known in trial.read):
        trial.read.append((name, arg))
    return None


@contextmanager
def _trying(trial: _Trial) -> Iterator[None]:
    token = _TRIAL.set(trial)
    try:
        yield
    finally:
        _TRIAL.reset(token)


def _outcome(decide: Callable[[], bool], trial: _Trial) -> bool | None:
    """The condition under the trial: None when it still cannot be decided; False when launch
    would reject it (no run has that value)."""
    with _trying(trial):
        try:
            return decide()
        except Unresolved:
            return None
        except (SubstitutionError, LaunchError):
            return False
        except (budget.BudgetExceeded, RecursionError):
            return None


@dataclass(frozen=True)
class Guard:
    """An undecided condition that depends on one unknown launch argument alone."""

    name: str
    arg: UnknownArg
    values: tuple[str, ...]  # the words and strings it is written with
    decide: Callable[[], bool]

    def may_hold(self, value: str) -> bool:
        """Whether the condition can hold with the argument set to `value` (undecided counts)."""
        return _outcome(self.decide, _Trial({id(self.arg): value})) is not False


def guard(text: str, decide: Callable[[], bool]) -> Guard | None:
    """The guard of an undecided condition written `text` and evaluated by `decide`, or None when it
    does not depend on exactly one unknown argument."""
    probe = _Trial({})
    _outcome(decide, probe)
    if len(probe.read) != 1:
        return None
    name, arg = probe.read[0]
    if _outcome(decide, _Trial({id(arg): OTHER})) is None:  # something else is unknown too
        return None
    words = {word for pattern in _WORDS for word in pattern.findall(text)}
    return Guard(name, arg, tuple(sorted(words | {"true", "false", "1", "0", ""})), decide)


def settle(nodes: list[LaunchNode]) -> None:
    """Each conditional node's `when`: for every unknown argument its conditions depend on, the
    values (of those tried) for which they may all hold; left None when a condition of the node
    depends on something else, or holds for none of the values tried (or when the trials' budget is spent)."""
    keys: dict[int, str] = {}
    tried: dict[int, set[str]] = {}
    for node in nodes:
        for one in node.guards:
            if one is not None:
                keys.setdefault(id(one.arg), f"{one.name}#{len(keys) + 1}")
                tried.setdefault(id(one.arg), set()).update(one.values)
    trials = 0
    for node in nodes:
        if not node.condition or not node.guards or any(one is None for one in node.guards):
            continue
        trials += sum(min(len(tried[id(g.arg)]), _MAX_VALUES) + 1 for g in node.guards if g is not None)
        if trials > _MAX_TRIALS:
            return
        when: dict[str, frozenset[str]] = {}
        for one in (g for g in node.guards if g is not None):
            values = sorted(tried[id(one.arg)])[:_MAX_VALUES] + [OTHER]
            key = keys[id(one.arg)]
            holds = frozenset(v for v in values if one.may_hold(v))
            when[key] = when[key] & holds if key in when else holds
        if all(when.values()):  # a condition that holds for no value tried was not understood
            node.when = when
