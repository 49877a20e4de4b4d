"""Values recovered by static analysis: known strings, parameter reads, and explicit unknowns."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Unknown:
    """A value static analysis cannot know; records the expression and where it was met."""

    expr: str
    file: str
    line: int

    def __str__(self) -> str:
        return f"?({self.expr})"


@dataclass(frozen=True)
class ParamRef:
    """A value read from a ROS parameter (`name` as written in the source) with its default."""

    name: str
    default: "Value"
    handle_ns: str = ""
    file: str = ""
    line: int = 0


@dataclass(frozen=True)
class Concat:
    """A string built from parts at least one of which is not a literal."""

    parts: tuple["Value", ...]


Value = str | Unknown | ParamRef | Concat


def concat(*parts: Value) -> Value:
    """Join values; literal neighbours fold into one string."""
    folded: list[Value] = []
    for part in parts:
        pieces = part.parts if isinstance(part, Concat) else (part,)
        for piece in pieces:
            if isinstance(piece, str) and folded and isinstance(folded[-1], str):
                folded[-1] += piece
            elif piece != "":
                folded.append(piece)
    if not folded:
        return ""
    return folded[0] if len(folded) == 1 else Concat(tuple(folded))
