"""The period of an endless loop in C++ (behavior.py): the ros::Rate / rclcpp::Rate it sleeps
on, else its sleeps added up (ros::Duration::sleep, usleep, sleep, std::this_thread::sleep_for),
in seconds; a rate from a parameter counts with the parameter's default."""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import CursorKey, K, period, qualified, strip, written_args
from archlog.extract.cpp.index import Host
from archlog.extract.cpp.state import object_of
from archlog.extract.qos import number, seconds_text
from archlog.values import ParamRef, Unknown, Value

RATES = ("ros::Rate", "ros::WallRate", "rclcpp::Rate", "rclcpp::WallRate", "rclcpp::GenericRate", "rclcpp::RateBase")
DURATIONS = ("ros::Duration", "ros::WallDuration", "ros::DurationBase")
SLEEPS = ("sleep", "usleep", "sleep_for", "nanosleep")


class Periods:
    """Loop periods; `flows` holds what is stored in each variable (a rate member's construction),
    `passed` what the calls of a function pass for a parameter (a rate handed to a thread)."""

    def __init__(self, host: Host, flows: dict[CursorKey, list[ci.Cursor]],
                 passed: Callable[[ci.Cursor], list[ci.Cursor]]) -> None:
        self.host, self.flows, self.passed = host, flows, passed
        self._memo: dict[CursorKey, Value] = {}

    def of(self, loop: ci.Cursor) -> Value:
        """Seconds between iterations: the Rate slept on, else the sleeps of the body added up."""
        memo = self.host.key(loop)
        if memo in self._memo:
            return self._memo[memo]
        rate: Value | None = None
        total: Fraction | None = Fraction(0)
        slept = False
        for cursor in loop.walk_preorder():
            if cursor.kind != K.CALL_EXPR or cursor.spelling not in SLEEPS:
                continue
            slept = True
            seconds = self.sleep(cursor)
            if isinstance(seconds, tuple):
                rate = rate or seconds[0]
            elif seconds is not None and total is not None:
                total += seconds
            else:
                total = None
        if rate is not None:
            found: Value = rate
        elif slept and total:
            found = seconds_text(total)
        else:
            found = Unknown("sleep not constant" if slept else "loop without a sleep", self.host.shown(loop),
                            loop.location.line)
        self._memo[memo] = found
        return found

    def sleep(self, call: ci.Cursor) -> Fraction | tuple[Value] | None:
        """A sleep's duration in seconds; a Rate's period as a 1-tuple (it sets the loop's period)."""
        args = written_args(call)
        owner = qualified(call.referenced.semantic_parent) if call.referenced is not None else ""
        if call.spelling == "sleep" and owner in RATES:
            obj = object_of(call)
            return (self.rate(obj) if obj is not None else self.host.unknown(call, "rate not known"),)
        if call.spelling == "sleep" and owner in DURATIONS:
            obj = object_of(call)
            ctor = self.constructed(obj) if obj is not None else None
            return _seconds(self.host.value(written_args(ctor)[0])) if ctor is not None else None
        if call.spelling == "usleep" and args:
            amount = _seconds(self.host.value(args[0]))
            return amount / 1_000_000 if amount is not None else None
        if call.spelling == "sleep" and args and not owner:
            return _seconds(self.host.value(args[0]))
        if call.spelling == "sleep_for" and args:
            return self.host.seconds(args[0])
        return None

    def constructed(self, expr: ci.Cursor) -> ci.Cursor | None:
        """The constructor call (with arguments) that made an object: a temporary, a variable's
        initializer, what is stored in a member (`rate_(10)`, `rate_ = std::make_shared<rclcpp::Rate>(10)`)."""
        expr = strip(expr)
        candidates = [expr]
        if expr.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and expr.referenced is not None:
            candidates = self.flows.get(self.host.key(expr.referenced), [])
        for candidate in candidates:
            for cursor in candidate.walk_preorder():
                if cursor.kind == K.CALL_EXPR and written_args(cursor) and cursor.spelling != "operator->":
                    return cursor
        return None

    def rate(self, obj: ci.Cursor) -> Value:
        """The period of a Rate object: 1/hz, or its duration."""
        ctor = self.constructed(obj)
        args = written_args(ctor) if ctor is not None else []
        if not args:
            return self.host.unknown(obj, "rate not constant")
        if "duration" in args[0].type.get_canonical().spelling:
            seconds = self.host.seconds(args[0])
            return seconds_text(seconds) if seconds else self.host.unknown(ctor, "rate not constant")
        hz = self.host.value(args[0])
        inner = strip(args[0])
        param = inner.referenced if inner.kind == K.DECL_REF_EXPR else None
        passed = self.passed(param) if param is not None and param.kind == K.PARM_DECL else []
        if isinstance(hz, Unknown) and len(passed) == 1:  # a parameter of a function run in a thread
            hz = self.host.value(passed[0])
        if isinstance(hz, ParamRef) and isinstance(hz.default, str):
            hz = hz.default
        return period(hz) if isinstance(hz, str) and number(hz) else self.host.unknown(ctor, "rate not constant")


def _seconds(value: Value | None) -> Fraction | None:
    """A number of seconds, a parameter's default if it is one."""
    if isinstance(value, ParamRef):
        value = value.default
    return number(value) if isinstance(value, str) else None
