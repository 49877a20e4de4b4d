"""Python 2 (and broken) sources: repaired line by line, where parso points, so that their ROS
calls are still recovered; and the guard against code nested deeper than the parser allows."""

from __future__ import annotations

import ast
import re

import parso


class NestedTooDeeply(Exception):
    """Code nested deeper than Python's parser allows (brackets, indentation, expressions)."""

    def __init__(self, line: int) -> None:
        super().__init__(f"nested too deeply at line {line}")
        self.line = line


# applied to lines without trailing blanks, so that no pattern backtracks over a run of them
_REPAIRS = [
    (re.compile(r"^(\s*)print\s*>>\s*[^,]+,\s*(.*)$"), r"\1print(\2)"),
    (re.compile(r"^(\s*)print\s+(?!\()(.*)$"), r"\1print(\2)"),
    (re.compile(r"^(\s*)print$"), r"\1print()"),
    (re.compile(r"^(\s*except\s+[^,:]+),\s*(\w+)\s*:"), r"\1 as \2:"),
    (re.compile(r"^(\s*)exec\s+(?!\()(.*)$"), r"\1exec(\2)"),
    (re.compile(r"^(\s*raise\s+[\w.]+)\s*,\s*(.+)$"), r"\1(\2)"),
    (re.compile(r"\b0([0-7]+)\b"), r"0o\1"),
    (re.compile(r"\b(\d+)[lL]\b"), r"\1"),
    (re.compile(r"\bur(['\"])"), r"u\1"),
    (re.compile(r"<>"), "!="),
    (re.compile(r"`([^`]*)`"), r"repr(\1)"),
    # newer than the running Python (3.12 type statements and generic parameter lists)
    (re.compile(r"^(\s*)type\s+(\w+)\s*(?:\[[^\]]*\])?\s*="), r"\1\2 ="),
    (re.compile(r"^(\s*(?:async\s+)?def\s+\w+)\[[^\]]*\]\s*\("), r"\1("),
    (re.compile(r"^(\s*class\s+\w+)\[[^\]]*\]"), r"\1"),
]


REPAIR_LINES = 20_000
"""Longest source that is repaired (parso reads ~10k lines a second); longer ones that do not
parse are reported, not repaired."""
_TOO_DEEP = ("too many nested parentheses", "too many levels of indentation")
_REPAIR_ROUNDS = 6  # parso passes; each finds every error it can, so Python 2 needs one or two


def _python2_indent(line: str) -> str:
    """The line with its indentation's tabs expanded as Python 2 reads them (to the next multiple
    of 8 columns), so that a file mixing tabs and spaces parses under Python 3."""
    body = line.lstrip(" \t")
    return line[: len(line) - len(body)].expandtabs(8) + body


def _parse(text: str) -> ast.Module:
    """ast.parse; a NUL byte is a SyntaxError on every Python 3.11 (a ValueError before 3.11.4)."""
    try:
        return ast.parse(text)
    except ValueError as exc:
        raise SyntaxError(str(exc)) from None


def parse_tolerant(source: str) -> tuple[ast.Module | None, list[int], list[int]]:
    """Parse with ast; on failure repair the lines parso (error recovery) or ast points at:
    first with Python 2 rewrites (tabs in indentation expanded as Python 2 does), then by
    neutralising the statement. Line numbers never move.
    Returns the tree, the repaired lines, and those of them whose statement was dropped.
    Raises NestedTooDeeply for code nested deeper than Python's parser allows."""
    lines = source.splitlines()
    repaired: dict[int, None] = {}  # in the order repaired
    dropped: list[int] = []
    tabs_expanded = False
    grammar = parso.load_grammar()
    budget = max(10, len(lines) // 4)  # past this many repairs the file is not Python 2 either
    for _round in range(_REPAIR_ROUNDS + 1):
        try:
            return _parse("\n".join(lines) + "\n"), list(repaired), dropped
        except (RecursionError, MemoryError):
            raise NestedTooDeeply(1) from None
        except SyntaxError as exc:
            if exc.msg in _TOO_DEEP:
                raise NestedTooDeeply(exc.lineno or 1) from None
            expanded = lines if tabs_expanded else [_python2_indent(line) for line in lines]
            tabs_expanded = True
            tabbed = next((n for n, (a, b) in enumerate(zip(lines, expanded), 1) if a != b), None)
            if tabbed is not None:
                lines, repaired[tabbed] = expanded, None
                continue
            if len(lines) > REPAIR_LINES or len(repaired) > budget or _round == _REPAIR_ROUNDS:
                break
            bad = sorted({e.start_pos[0] for e in grammar.iter_errors(grammar.parse("\n".join(lines)))}
                         | {exc.lineno or 1})
        progress = False
        for line_number in bad:
            if not 1 <= line_number <= len(lines):
                continue
            text = lines[line_number - 1].rstrip()
            fixed = text
            for pattern, replacement in _REPAIRS:
                fixed = pattern.sub(replacement, fixed)
            if fixed == text:
                indent = text[: len(text) - len(text.lstrip())]
                fixed = indent + ("if True:" if text.rstrip().endswith(":") else "pass")
                if fixed == text:
                    continue
                dropped.append(line_number)
            lines[line_number - 1] = fixed
            progress = True
            repaired[line_number] = None
        if not progress:
            break
    return None, list(repaired), dropped
