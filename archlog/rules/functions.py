"""The functions rules may call as `@name(...)`: string and ROS name helpers.

clingo calls them while grounding, with this module's `Functions` as the context: no other
Python is reachable from a rule (a rule file naming any other function is rejected when it loads).
A function given a value that is not a string (an unknown value `unknown(N)`, a number where a
name is expected) has no result, so the literal that uses it does not hold.
"""

from __future__ import annotations

from collections.abc import Callable

import clingo

from archlog import names

Result = clingo.Symbol | list[clingo.Symbol]


def _strings(function: Callable[..., Result]) -> Callable[..., Result]:
    """Take clingo strings (and numbers) to Python values; anything else gives no result."""

    def call(self: Functions, *args: clingo.Symbol) -> Result:
        values: list[str | int] = []
        for arg in args:
            if arg.type == clingo.SymbolType.String:
                values.append(arg.string)
            elif arg.type == clingo.SymbolType.Number:
                values.append(arg.number)
            else:
                return []
        try:
            return function(self, *values)
        except (TypeError, AttributeError):  # a number where a string is expected, or the other way round
            return []

    call.__doc__ = function.__doc__
    return call


def _segments(name: str) -> list[str]:
    return [s for s in name.split("/") if s]


class Functions:
    """`@parent("/a/b/c")` is "/a/b"; `@basename("/a/b/c")` is "c"; `@segments("/a/b/c")` is 3;
    `@prefix("/a/b/c", 2)` is "/a/b"; `@suffix("/a/b/c", 2)` is "b/c"; `@starts_with(S, P)` and
    `@ends_with(S, P)` are 1 or 0; `@lower(S)` is S in lower case; `@concat(A, B, ...)` joins strings;
    `@less(A, B)` compares numbers (numeric strings too), 1 or 0."""

    @_strings
    def parent(self, name: str) -> Result:
        """The namespace a name lives in ("/" for a name at the root; none for "/" itself)."""
        return clingo.String(names.namespace_of(name)) if _segments(name) else []

    @_strings
    def basename(self, name: str) -> Result:
        """The last segment of a name."""
        return clingo.String(_segments(name)[-1]) if _segments(name) else []

    @_strings
    def segments(self, name: str) -> Result:
        """The number of segments of a name ("/" has none)."""
        return clingo.Number(len(_segments(name)))

    @_strings
    def prefix(self, name: str, count: int) -> Result:
        """The namespace made of the first `count` segments of a global name."""
        parts = _segments(name)
        return clingo.String("/" + "/".join(parts[:count])) if 0 <= count <= len(parts) else []

    @_strings
    def suffix(self, name: str, count: int) -> Result:
        """The relative name made of the last `count` segments."""
        parts = _segments(name)
        return clingo.String("/".join(parts[len(parts) - count:])) if 0 <= count <= len(parts) else []

    @_strings
    def starts_with(self, text: str, start: str) -> Result:
        return clingo.Number(int(text.startswith(start)))

    @_strings
    def ends_with(self, text: str, end: str) -> Result:
        return clingo.Number(int(text.endswith(end)))

    @_strings
    def lower(self, text: str) -> Result:
        return clingo.String(text.lower())

    @_strings
    def concat(self, *parts: str | int) -> Result:
        """The parts (strings or numbers) joined into one string."""
        return clingo.String("".join(map(str, parts)))

    @_strings
    def less(self, a: str | int, b: str | int) -> Result:
        """1 when number a is below number b (either may be a numeric string such as "0.5"), else 0;
        none when either is not a number."""
        try:
            return clingo.Number(int(float(a) < float(b)))
        except ValueError:
            return []


FUNCTIONS = Functions()
NAMES = sorted(n for n in vars(Functions) if not n.startswith("_"))
