"""The statements of a file that change a QoS object or rmw profile after its declaration."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import CursorKey, K, binary_operator, qualified, strip
from archlog.extract.cpp.rclcpp.api import chain_root

_CONDITIONAL = (K.IF_STMT, K.FOR_STMT, K.WHILE_STMT, K.DO_STMT, K.SWITCH_STMT, K.CXX_FOR_RANGE_STMT,
                K.CONDITIONAL_OPERATOR, K.CASE_STMT, K.DEFAULT_STMT)


@dataclass
class Mutation:
    """A statement changing a QoS object or rmw profile: `qos.best_effort();`, `p.depth = 5;`."""

    offset: int
    expr: ci.Cursor
    conditional: bool


class KeyOf(Protocol):
    """What recording changes needs of the walker: the key of a declaration."""

    def key(self, decl: ci.Cursor | None) -> CursorKey: ...


class QosChanges:
    """Records, per QoS variable or member, the statements changing it and whether they run
    only under a condition."""

    def __init__(self, ctx: KeyOf) -> None:
        self.ctx = ctx
        self.mutations: dict[CursorKey, list[Mutation]] = {}

    def statements(self, block: ci.Cursor, conditional: bool) -> None:
        """Record the statements of a function body that change a QoS object, and whether they
        run only under a condition."""
        for stmt in block.get_children():
            if stmt.kind == K.COMPOUND_STMT:
                self.statements(stmt, conditional)
            elif stmt.kind in _CONDITIONAL:
                for child in stmt.get_children():
                    if child.kind == K.COMPOUND_STMT:
                        self.statements(child, True)
                    else:
                        self.mutation(child, True)
            else:
                self.mutation(stmt, conditional)

    def mutation(self, stmt: ci.Cursor, conditional: bool) -> None:
        expr = strip(stmt)
        root: ci.Cursor | None = None
        if expr.kind == K.CALL_EXPR and expr.referenced is not None and \
                qualified(expr.referenced.semantic_parent) == "rclcpp::QoS":
            root = strip(next(expr.get_children())) if expr.spelling == "operator=" else chain_root(expr)
        elif expr.kind == K.BINARY_OPERATOR and binary_operator(expr) == "=":
            lhs = strip(next(expr.get_children()))
            root = lhs if lhs.kind == K.DECL_REF_EXPR else \
                next((c for c in lhs.get_children() if c.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR)), lhs)
        if root is not None and root.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and root.referenced is not None:
            self.mutations.setdefault(self.ctx.key(root.referenced), []).append(
                Mutation(expr.extent.start.offset, expr, conditional))
