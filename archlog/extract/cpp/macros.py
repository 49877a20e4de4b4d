"""Macro bombs: macros of a C++ file or its workspace headers whose expansion, or nesting of
calls that copy their argument, would pass MACRO_TOKENS tokens (checked before libclang parses)."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from archlog.extract.cpp.clang_ast import line_finder

MACRO_TOKENS = 1_000_000
"""Most tokens one macro of the workspace may expand to (`#define A1 A0 A0`, ... doubles)."""
_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(\w+)(\([^)\n]*\))?(.*)$", re.M)
_WORD = re.compile(r"\w+")
_CALL_OR_PAREN = re.compile(r"(\w+)\s*\(|[()]")


@dataclass(frozen=True)
class Macro:
    """A #define: where it is, the words of its body, and how often it copies a parameter."""

    file: Path
    line: int
    words: list[str]  # of its body
    copies: int = 1  # function-like: the most times its body uses one parameter


def defines(path: Path, text: str) -> dict[str, Macro]:
    """The macros a file defines, by name."""
    found, line_of = {}, line_finder(text)
    for m in _DEFINE.finditer(text):
        words = _WORD.findall(m.group(3))
        params = _WORD.findall(m.group(2) or "")
        # a parameter the body never uses is copied 0 times: count it as 1 (nested calls vanish, never divide by 0)
        found[m.group(1)] = Macro(path, line_of(m.start()), words, max([1, *(words.count(p) for p in params)]))
    return found


def nested_calls(texts: list[tuple[Path, str]], macros: dict[str, Macro]) -> tuple[Path, int, str] | None:
    """(file, line, name) where calls of function-like macros that copy their argument nest so
    deep that the copies pass MACRO_TOKENS (`#define F(x) x x` and F(F(F(...))))."""
    for path, text in texts:
        product, stack = 1, list[int]()  # the copies so far, and before each open call
        for m in _CALL_OR_PAREN.finditer(text):
            if m.group(0) == ")":
                product = stack.pop() if stack else product
                continue
            copies = macros[m.group(1)].copies if m.group(1) in macros else 1
            stack.append(product)
            product *= copies  # 0 for a macro that drops its argument: nothing inside is copied
            if product > MACRO_TOKENS:
                return path, line_finder(text)(m.start()), m.group(1)
    return None


def macro_bomb(macros: dict[str, Macro]) -> tuple[Path, int, str] | None:
    """(file, line, name) of a macro whose expansion passes MACRO_TOKENS words, else None. Sizes
    are computed bottom-up without recursion; a macro met again while expanding counts one word."""
    size: dict[str, int] = {}
    for root in (name for name in macros if name not in size):
        stack, open_ = [(root, iter(macros[root].words))], {root}
        while stack:
            name, words = stack[-1]
            child = next((w for w in words if w in macros and w not in size and w not in open_), None)
            if child is not None:
                stack.append((child, iter(macros[child].words)))
                open_.add(child)
                continue
            stack.pop()
            open_.discard(name)
            size[name] = sum(size.get(w, 1) if w in macros else 1 for w in macros[name].words)
            if size[name] > MACRO_TOKENS:
                return macros[name].file, macros[name].line, name
    return None
