"""Edits that cut the start of a string variable before it is used as a name: `ns.erase(0, 1)` (often
under `if (!ns.empty() && ns[0] == '/')`), `ns.erase(ns.begin())`, `ns = ns.substr(1)`. roscpp code
makes a handle's namespace relative so (NodeHandle::getNamespace() starts with the slash)."""

from __future__ import annotations

from dataclasses import replace
from typing import NamedTuple

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import K, written_args
from archlog.values import Namespace, Unknown, Value

# the words of a condition that only tests a string's first character or emptiness
_SLASH_TEST = {".", "empty", "size", "length", "front", "at", "(", ")", "[", "]", "0", "1", "!", "&&", "==", ">",
               "'/'", "->"}


def cut(value: Value, count: int, guarded: bool, at: Unknown) -> Value:
    """`value` less its first `count` characters; when `guarded`, only if it starts with a slash."""
    if isinstance(value, str):
        return value if guarded and not value.startswith("/") else value[count:]
    if isinstance(value, Namespace) and not (guarded and value.cut):  # uncut, a namespace starts with "/"
        return replace(value, cut=value.cut + count)
    return at


def leading_cut(call: ci.Cursor) -> int | None:
    """How many leading characters an `erase` or `substr` call removes (substr: keeps the rest), or None:
    erase(0, n), erase(begin()), substr(n)."""
    args = written_args(call)
    numbers = [_number(a) for a in args]
    if call.spelling == "substr" and len(args) == 1:
        return numbers[0]
    if call.spelling == "erase" and len(args) == 2 and numbers[0] == 0:
        return numbers[1]
    if call.spelling == "erase" and len(args) == 1 and any(c.spelling == "begin" for c in args[0].walk_preorder()):
        return 1
    return None


class Edit(NamedTuple):
    """One edit of a variable: where it is, how many leading characters it cuts (`cuts`; None when it is not
    understood: in a loop, under a condition other than a test of the leading slash, in an else
    branch, or not a cut of the start), and whether a test of the leading slash guards it."""

    file: str
    offset: int
    cuts: int | None
    guarded: bool


def edits(decl: ci.Cursor) -> list[Edit]:
    """The edits made to string variable `decl` in its function, in order."""
    scope = decl.semantic_parent
    found = []
    for call, conditions in _edit_calls(scope, decl, []) if scope is not None else []:
        count = leading_cut(call)
        understood = all(c is not None and _tests_slash(c, decl.spelling) for c in conditions)
        found.append(Edit(call.location.file.name if call.location.file else "", call.extent.start.offset,
                          count if understood else None, bool(conditions)))
    return found


def before(found: list[Edit], use: ci.Cursor) -> list[Edit]:
    """The edits that precede `use` in its file."""
    file = use.location.file.name if use.location.file else ""
    return [e for e in found if e.file == file and e.offset < use.extent.start.offset]


def self_edit(rhs: ci.Cursor, decl: ci.Cursor) -> bool:
    """An assigned value that is the variable itself cut (`ns = ns.substr(1)`): an edit, not another value."""
    call = next((c for c in rhs.walk_preorder() if c.kind == K.CALL_EXPR and c.spelling == "substr"), None)
    return call is not None and _is(_edited(call), decl)


def _edit_calls(cursor: ci.Cursor, decl: ci.Cursor,
                conditions: list[ci.Cursor | None]) -> list[tuple[ci.Cursor, list[ci.Cursor | None]]]:
    """The erase calls on `decl` and assignments `decl = decl.substr(...)` under `cursor`, each with the
    conditions it is under (None for a loop or an else branch, which are not understood)."""
    if cursor.kind == K.CALL_EXPR and cursor.spelling == "erase" and _is(_edited(cursor), decl):
        return [(cursor, conditions)]
    if cursor.kind in (K.CALL_EXPR, K.BINARY_OPERATOR) and cursor.spelling in ("operator=", "="):
        parts = list(cursor.get_children())
        target = next((c.referenced for c in parts[0].walk_preorder() if c.kind == K.DECL_REF_EXPR), None) \
            if parts else None
        if _is(target, decl) and self_edit(parts[-1], decl):
            return [(next(c for c in parts[-1].walk_preorder() if c.spelling == "substr"), conditions)]
    children = list(cursor.get_children())
    found = []
    for index, child in enumerate(children):
        under = conditions
        if cursor.kind == K.IF_STMT and index > 0:
            under = conditions + [children[0] if index == 1 else None]
        elif cursor.kind in (K.WHILE_STMT, K.FOR_STMT, K.DO_STMT, K.CXX_FOR_RANGE_STMT):
            under = conditions + [None]
        found += _edit_calls(child, decl, under)
    return found


def _edited(call: ci.Cursor) -> ci.Cursor | None:
    """The variable a member call (`ns.erase(...)`) is made on."""
    member = next(call.get_children(), None)
    if member is None or member.kind != K.MEMBER_REF_EXPR:
        return None
    return next((c.referenced for c in member.walk_preorder() if c.kind == K.DECL_REF_EXPR), None)


def _is(cursor: ci.Cursor | None, decl: ci.Cursor) -> bool:
    return cursor is not None and cursor == decl  # (comparing a cursor with None raises)


def _tests_slash(condition: ci.Cursor, name: str) -> bool:
    return all(t.spelling in _SLASH_TEST or t.spelling == name for t in condition.get_tokens())


def _number(arg: ci.Cursor) -> int | None:
    tokens = [t.spelling for t in arg.get_tokens()]
    return int(tokens[0]) if len(tokens) == 1 and tokens[0].isdigit() else None
