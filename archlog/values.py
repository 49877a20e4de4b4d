"""Values recovered by static analysis: known strings, parameter reads, and explicit unknowns."""

from __future__ import annotations

import math
from dataclasses import dataclass

from archlog import budget


@dataclass(frozen=True)
class Unknown:
    """A value static analysis cannot know; records the expression and where it was met.

    Written `?(expr)` wherever archlog prints or writes a value (tables, CSV, JSON, messages,
    explanations); in rules it is the term `unknown(N)` that `unknown_value` describes. A string
    built from known and unknown parts (`ns + "/scan"`) keeps what it is known to start and end
    with in `prefix` and `suffix` ("" when nothing is known); `unknown_pattern` gives them to rules."""

    expr: str
    file: str
    line: int
    prefix: str = ""
    suffix: str = ""

    def __str__(self) -> str:
        return f"?({self.expr})"

    def fits(self, text: str) -> bool:
        """Whether the value might be `text`: it starts with the known prefix and ends with the known suffix."""
        return text.startswith(self.prefix) and text.endswith(self.suffix)

    def vague(self) -> Unknown:
        """The same unknown with nothing known of its parts."""
        return Unknown(self.expr, self.file, self.line)


def partly_known(parts: tuple[str | Unknown, ...]) -> Unknown:
    """The unknown string joining `parts` (at least one unknown): it starts with the first part (or
    that part's known prefix) and ends with the last (or that part's known suffix)."""
    unknown = next(p for p in parts if isinstance(p, Unknown))
    first, last = parts[0], parts[-1]
    return Unknown(" + ".join(p.expr if isinstance(p, Unknown) else repr(p) for p in parts), unknown.file,
                   unknown.line, first.prefix if isinstance(first, Unknown) else first,
                   last.suffix if isinstance(last, Unknown) else last)


def order(cell: str | int | Unknown) -> tuple[int, str | int, str, int]:
    """A sort key for any cell: numbers, then strings, then unknowns (by expression, file, line)."""
    if isinstance(cell, Unknown):
        return (2, cell.expr, cell.file, cell.line)
    return (0, cell, "", 0) if isinstance(cell, int) else (1, cell, "", 0)


class FullNodeName(str):
    """A name that starts with ros::this_node::getName(), the node's full name. Written with "~"
    (it resolves as the private namespace does), but it is not a ~name: a NodeHandle accepts it."""

    __slots__ = ()


@dataclass(frozen=True)
class OverBudget(Unknown):
    """A value that would stand for more alternatives than archlog follows (MAX_ALTERNATIVES for
    one value, the budget's `alternatives` for all combinations); a port named by it is a
    budget-exceeded diagnostic at the call."""


@dataclass(frozen=True)
class ParamRef:
    """A value read from a ROS parameter (`name` as written in the source) with its default."""

    name: Value
    default: Value
    handle_ns: Value = ""
    file: str = ""
    line: int = 0


@dataclass(frozen=True)
class ParamList:
    """Names taken from a list parameter, one per element (the element itself, or its `field`):
    twist_mux's `~topics: [{name: joy, topic: joy_vel}, ...]`. With `entry`, the parameter names a
    YAML file and the names are in that file's `entry` (a list as above, or one name; `default`
    when the file lacks it): yocs_cmd_vel_mux's `~yaml_cfg_file` (system/param_files.py).
    `defaults`: the list the node uses when the configuration does not set the parameter (a
    Python `rospy.get_param("~topics", ["scan"])`)."""

    name: str
    field: str = ""
    file: str = ""
    line: int = 0
    entry: str = ""
    default: str | None = None
    defaults: tuple[str, ...] | None = None


@dataclass(frozen=True)
class Concat:
    """A string built from parts at least one of which is not a literal."""

    parts: tuple[Value, ...]


@dataclass(frozen=True)
class Alternatives:
    """Several possible values: one of them at run time (a ternary, if/else assignments), or, with
    `every`, all of them (a loop over a literal list: each iteration makes its own port)."""

    options: tuple[Value, ...]
    every: bool = False


@dataclass(frozen=True)
class Namespace:
    """What roscpp's NodeHandle::getNamespace() returns (ros::this_node::getNamespace() is the node's own
    handle's): the handle's namespace resolved and remapped in the node instance ("/" at the root), less
    the first `cut` characters string edits removed (`ns.erase(0, 1)`, `ns.substr(1)`). `handle` is the
    handle's namespace as written ("" for the node's own, "~" for its private one)."""

    handle: Value = ""
    cut: int = 0


@dataclass(frozen=True)
class Switch:
    """A value a test of another value chooses: `when_equal` where `subject` is `equals`, else
    `otherwise` (Python's `if x != '': x = '/' + x` after `x` was read from a parameter: which one
    holds is decided per node instance, when the parameter's value is known)."""

    subject: Value
    equals: str
    when_equal: Value
    otherwise: Value


Value = str | Unknown | ParamRef | ParamList | Concat | Alternatives | Namespace | Switch
MAX_ALTERNATIVES = 16


def alternatives(options: list[Value], every: bool, at: Unknown) -> Value:
    """Alternatives of distinct values; one value stands alone; too many or unknown ones: `at`."""
    distinct = list(dict.fromkeys(options))
    if any(isinstance(o, Unknown) for o in distinct) or not distinct or len(distinct) > MAX_ALTERNATIVES:
        return at
    return distinct[0] if len(distinct) == 1 else Alternatives(tuple(distinct), every)


def concat(*parts: Value) -> Value:
    """Join values; literal neighbours fold into one string; alternatives distribute (unless they
    would stand for more combinations than the budget's alternatives: then the value is unknown)."""
    combinations = math.prod(len(p.options) for p in parts if isinstance(p, Alternatives))
    if combinations > (limit := budget.current().limits["alternatives"]):
        return OverBudget(f"{combinations} alternatives, more than the budget allows ({limit})", "", 0)
    for index, part in enumerate(parts):
        if isinstance(part, Alternatives):
            every, options = part.every, list[Value]()
            for option in part.options:
                joined = concat(*parts[:index], option, *parts[index + 1:])
                if isinstance(joined, Alternatives):  # several alternative parts: all combinations
                    every = every and joined.every
                    options += joined.options
                else:
                    options.append(joined)
            if len(options) > MAX_ALTERNATIVES:
                return OverBudget(f"more than {MAX_ALTERNATIVES} alternatives", "", 0)
            return Alternatives(tuple(dict.fromkeys(options)), every)
    folded: list[Value] = []
    for part in parts:
        pieces = part.parts if isinstance(part, Concat) else (part,)
        for piece in pieces:
            if isinstance(piece, str) and folded and isinstance(folded[-1], str):
                joined = folded[-1] + piece
                folded[-1] = FullNodeName(joined) if isinstance(folded[-1], FullNodeName) else joined
            elif piece != "":
                folded.append(piece)
    if not folded:
        return ""
    return folded[0] if len(folded) == 1 else Concat(tuple(folded))
