"""Ports made only when a parameter says so: `if (use_indices_) sub = nh.subscribe("indices", ...)`,
where use_indices_ was read from a parameter, exists only when the parameter (or, when it is not
set, the variable's initial value) is true; the port carries that condition (Port.condition), and
those of the branches around it (Port.also): in the `else` of `if (a)` inside `if (a || b)`, a is
false and so b is true."""

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

    def around(self, call: ci.Cursor) -> list[tuple[ci.Cursor, bool]]:
        """The conditions of the branches around a call, innermost first, and whether each must hold."""
        if call.location.file is None:
            return []
        at, file = call.extent.start.offset, call.location.file.name
        around = sorted((s for s in self.spans if s[0] == file and s[1] <= at <= s[2]), key=lambda s: -s[1])
        return [(condition, taken) for _file, _start, _end, condition, taken in around[:_DEPTH]]


Literal = tuple[ci.Cursor, bool]  # a variable and the truth value a condition needs it to have
_DEPTH = 8  # enclosing branches read


def required(branches: list[tuple[ci.Cursor, bool]]) -> list[Literal]:
    """The variables that must be true or false for every branch to be taken (innermost first):
    the tests of `x`, `!x`, `x && y` (when it holds), `x || y` (when it does not), and of `x || y`
    when the others leave one of its variables to decide. What is not one of those is left out
    (a weaker condition: the port is kept more often)."""
    known: list[Literal] = []
    clauses: list[list[Literal]] = []
    for condition, holds in branches:
        _literals(condition, holds, known, clauses)
    settled = True
    while settled:  # a clause whose other variables the known ones make false decides its last one
        settled = False
        for clause in clauses:
            if any(lit[0] == k[0] and lit[1] == k[1] for lit in clause for k in known):
                continue
            undecided = [lit for lit in clause if all(lit[0] != k[0] for k in known)]
            if len(undecided) == 1:
                known.append(undecided[0])
                settled = True
    return known


def _literals(condition: ci.Cursor, holds: bool, known: list[Literal], clauses: list[list[Literal]],
              depth: int = 0) -> None:
    """What a condition that holds (or not) requires: literals, or a clause (one of them)."""
    condition, holds = _bare(condition, holds)
    binary = _binary(condition)
    if binary is not None and depth < _DEPTH:
        operator, left, right = binary
        if operator == ("&&" if holds else "||"):  # both parts
            _literals(left, holds, known, clauses, depth + 1)
            _literals(right, holds, known, clauses, depth + 1)
        elif operator == ("||" if holds else "&&") and (clause := _clause(condition, holds, depth)):
            clauses.append(clause)
    elif condition.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and condition.referenced is not None:
        known.append((condition.referenced, holds))


def _clause(condition: ci.Cursor, holds: bool, depth: int) -> list[Literal] | None:
    """`x || y` that holds (or `x && y` that does not) as the variables one of which must be as
    given; None when a part is not a variable."""
    condition, holds = _bare(condition, holds)
    binary = _binary(condition)
    if binary is not None and depth < _DEPTH and binary[0] == ("||" if holds else "&&"):
        left, right = _clause(binary[1], holds, depth + 1), _clause(binary[2], holds, depth + 1)
        return None if left is None or right is None else left + right
    if condition.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and condition.referenced is not None:
        return [(condition.referenced, holds)]
    return None


def _binary(condition: ci.Cursor) -> tuple[str, ci.Cursor, ci.Cursor] | None:
    children = [c for c in condition.get_children() if c.kind not in SKIP]
    if condition.kind != K.BINARY_OPERATOR or len(children) != 2:
        return None
    return _operator(condition, children[0]), children[0], children[1]


def _bare(condition: ci.Cursor, holds: bool) -> tuple[ci.Cursor, bool]:
    """A condition without parentheses, implicit conversions and negations (each flips `holds`)."""
    for _ in range(_DEPTH * 4):
        children = [c for c in condition.get_children() if c.kind not in SKIP]
        if condition.kind == K.UNARY_OPERATOR and [t.spelling for t in condition.get_tokens()][:1] == ["!"] \
                and len(children) == 1:
            condition, holds = children[0], not holds
        elif condition.kind in (K.UNEXPOSED_EXPR, K.PAREN_EXPR) and len(children) == 1:
            condition = children[0]
        else:
            break
    return condition, holds


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
