"""Durations in C++ code, in seconds: chrono literals and durations, rclcpp::Duration, rmw_time_t."""

from __future__ import annotations

import re
from fractions import Fraction
from typing import Protocol

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import SKIP, K, qualified, strip, written_args
from archlog.extract.cpp.rclcpp.api import macro_name, tokens
from archlog.extract.qos import number, seconds_text
from archlog.values import Unknown, Value

CHRONO_LITERAL = re.compile(r"^(\d+(?:\.\d*)?|\.\d+)(h|min|s|ms|us|ns)$")
CHRONO_UNITS = {"h": Fraction(3600), "min": Fraction(60), "s": Fraction(1), "ms": Fraction(1, 1000),
                "us": Fraction(1, 1000000), "ns": Fraction(1, 1000000000)}
_CHRONO = re.compile(r"^std::(?:__\w+::)?chrono::duration<[^,<>]+(?:,\s*std::(?:__\w+::)?ratio<(\d+)[lLuU]*"
                     r"(?:,\s*(\d+)[lLuU]*)?>)?\s*>$")
_INFINITE = Fraction(9223372036)
_RMW_UNSPECIFIED = {"RMW_DURATION_UNSPECIFIED", "RMW_QOS_DEADLINE_DEFAULT", "RMW_QOS_LIFESPAN_DEFAULT",
                    "RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT", "RMW_QOS_DEADLINE_BEST_AVAILABLE",
                    "RMW_QOS_LIVELINESS_LEASE_DURATION_BEST_AVAILABLE"}


class Values(Protocol):
    """What reading durations needs of the walker: the value of an expression."""

    def value(self, expr: ci.Cursor, depth: int = 0) -> Value: ...
    def unknown(self, cursor: ci.Cursor, why: str = "") -> Unknown: ...


class Durations:
    """Reads durations and timer periods; used for rclcpp timers and QoS, and by behavior for
    the periods of timers of both ROS versions."""

    def __init__(self, ctx: Values) -> None:
        self.ctx = ctx

    def period(self, expr: ci.Cursor) -> Value:
        """A timer period in decimal seconds."""
        seconds = self.seconds(expr)
        return seconds_text(seconds) or self.ctx.unknown(expr, "zero period") if seconds is not None else \
            self.ctx.unknown(expr, "timer period not resolved")

    def seconds(self, expr: ci.Cursor, depth: int = 0) -> Fraction | None:
        """A duration in seconds: chrono literals (500ms), std::chrono durations, rclcpp::Duration,
        rmw_time_t {sec, nsec}; None when it is not known statically."""
        expr = strip(expr)
        if depth > 8:
            return None
        literal = CHRONO_LITERAL.match(tokens(expr).replace(" ", ""))
        if literal:
            return Fraction(literal.group(1)) * CHRONO_UNITS[literal.group(2)]
        if expr.kind == K.INIT_LIST_EXPR and not tokens(expr):  # from a macro: rmw's duration macros
            macro = macro_name(expr)
            return _INFINITE if macro == "RMW_DURATION_INFINITE" else Fraction(0) if macro in _RMW_UNSPECIFIED else None
        if expr.kind == K.INIT_LIST_EXPR:
            parts = [number(v) if isinstance(v := self.ctx.value(c, depth + 1), str) else None
                     for c in expr.get_children()]
            if len(parts) == 2 and parts[0] is not None and parts[1] is not None:
                return parts[0] + parts[1] / 1_000_000_000
            return None
        if expr.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and expr.referenced is not None and \
                expr.referenced.kind in (K.VAR_DECL, K.FIELD_DECL):
            init = [c for c in expr.referenced.get_children() if c.kind not in SKIP]
            return self.seconds(init[-1], depth + 1) if init and expr.referenced.type.is_const_qualified() else None
        if expr.kind != K.CALL_EXPR or expr.referenced is None:
            return None
        ref, args = expr.referenced, written_args(expr)
        owner = qualified(ref.semantic_parent)
        chrono = _CHRONO.match(expr.type.get_canonical().spelling)
        scale = Fraction(int(chrono.group(1) or 1), int(chrono.group(2) or 1)) if chrono else None
        if ref.kind == K.CONSTRUCTOR and owner == "rclcpp::Duration":
            if len(args) == 2:
                whole, nanos = (number(v) if isinstance(v := self.ctx.value(a, depth + 1), str) else None for a in args)
                return whole + nanos / 1_000_000_000 if whole is not None and nanos is not None else None
            return self.seconds(args[0], depth + 1) if args else None
        if owner == "rclcpp::Duration" and ref.spelling in ("from_seconds", "from_nanoseconds") and args:
            value = self.ctx.value(args[0], depth + 1)
            amount = number(value) if isinstance(value, str) else None
            return None if amount is None else amount if ref.spelling == "from_seconds" else amount / 1_000_000_000
        if ref.spelling == "duration_cast" and args:
            return self.seconds(args[0], depth + 1)
        if ref.kind == K.CONSTRUCTOR and scale is not None and len(args) == 1:
            inner = strip(args[0])
            if _CHRONO.match(inner.type.get_canonical().spelling):
                return self.seconds(inner, depth + 1)
            value = self.ctx.value(args[0], depth + 1)
            amount = number(value) if isinstance(value, str) else None
            return amount * scale if amount is not None else None
        if ref.kind == K.CONSTRUCTOR and len(args) == 1:  # copy or conversion
            return self.seconds(args[0], depth + 1)
        return None
