"""Ports made only when a parameter says so: `if (use_indices_) sub = nh.subscribe("indices", ...)`,
where use_indices_ was read from a parameter, exists only when the parameter (or, when it is not
set, the variable's initial value) is true; the port carries that condition (Port.condition)."""

from __future__ import annotations

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import SKIP, K


class Branches:
    """The if/else branches of a file's code: the condition each one requires, true or false."""

    def __init__(self, cursors: list[ci.Cursor]) -> None:
        self.spans: list[tuple[str, int, int, ci.Cursor, bool]] = []
        for cursor in cursors:
            if cursor.kind == K.IF_STMT and cursor.location.file is not None:
                children = list(cursor.get_children())
                if len(children) >= 2:
                    for branch, taken in zip(children[1:3], (True, False)):
                        self.spans.append((cursor.location.file.name, branch.extent.start.offset,
                                           branch.extent.end.offset, children[0], taken))

    def innermost(self, call: ci.Cursor) -> tuple[ci.Cursor, bool] | None:
        """The condition of the innermost branch around a call, and whether it must hold."""
        if call.location.file is None:
            return None
        at, file = call.extent.start.offset, call.location.file.name
        around = [s for s in self.spans if s[0] == file and s[1] <= at <= s[2]]
        if not around:
            return None
        _file, _start, _end, condition, taken = max(around, key=lambda s: s[1])
        return condition, taken


def tested_variable(condition: ci.Cursor, holds: bool = False) -> tuple[ci.Cursor, bool] | None:
    """The variable a condition tests, as `x` or `!x` (with True when negated), else None; where
    the condition `holds`, also the first operand of `x && ...`."""
    negated = False
    while True:
        children = [c for c in condition.get_children() if c.kind not in SKIP]
        if holds and not negated and condition.kind == K.BINARY_OPERATOR and len(children) == 2 and \
                _operator(condition, children[0]) == "&&":
            condition = children[0]
            continue
        if condition.kind == K.UNARY_OPERATOR and [t.spelling for t in condition.get_tokens()][:1] == ["!"] \
                and len(children) == 1:
            negated, condition = not negated, children[0]
        elif condition.kind in (K.UNEXPOSED_EXPR, K.PAREN_EXPR) and len(children) == 1:
            condition = children[0]
        elif condition.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and condition.referenced is not None:
            return condition.referenced, negated
        else:
            return None


def initial_value(field: ci.Cursor) -> ci.Cursor | None:
    """The expression a data member starts with: its in-class initializer, or the one its class's
    constructors agree on in their member initializer lists (the first found)."""
    own = [c for c in field.get_children() if c.kind not in SKIP and c.kind != K.TYPE_REF]
    if own:
        return own[-1]
    parent = field.semantic_parent
    for ctor in parent.get_children() if parent is not None else []:
        if ctor.kind != K.CONSTRUCTOR:
            continue
        children = list(ctor.get_children())
        for member, init in zip(children, children[1:]):
            if member.kind == K.MEMBER_REF and member.referenced == field:
                return init
    return None


def _operator(binary: ci.Cursor, left: ci.Cursor) -> str:
    """The operator of a binary expression: the token after its left operand."""
    tokens = [t.spelling for t in binary.get_tokens()]
    after = len(list(left.get_tokens()))
    return tokens[after] if after < len(tokens) else ""
