"""One pass over a C++ file's cursors for behavior (behavior.py): its functions and lambdas,
its publish calls, its writes (assignments, member initializers, container and pointer methods,
arguments passed by non-const reference), what is stored in each variable, and the calls that
register, hand on or invoke callbacks."""

from __future__ import annotations

import re
from collections.abc import Callable, Collection
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Protocol

import clang.cindex as ci

from archlog.extract.cpp.clang_ast import (
    SKIP,
    CursorKey,
    K,
    binary_operator,
    qualified,
    strip,
    unary_operator,
    written_args,
)
from archlog.extract.cpp.state import CONTAINER_WRITES, POINTER_WRITES, object_of, operands
from archlog.values import Unknown, Value

PUBLISH_CALLS = {
    "publish": ("ros::Publisher", "image_transport::Publisher", "image_transport::CameraPublisher",
                "rclcpp::Publisher", "rclcpp_lifecycle::LifecyclePublisher", "rclcpp::GenericPublisher"),
    "sendTransform": ("tf::TransformBroadcaster", "tf2_ros::TransformBroadcaster",
                      "tf2_ros::StaticTransformBroadcaster"),
}
# calls registering a callback: on an object that is a port (message_filters, actionlib,
# dynamic_reconfigure: its callback), or on anything else (a driver's data callback, a parameter
# callback, a signal, glutDisplayFunc: a callback of no port)
REGISTRATION = re.compile(r"callback|handler|func$|^connect$", re.I)
# calls whose callbacks run because of them (replies to requests), and thread launches
DEFERRED = ("sendGoal", "async_send_request", "async_send_goal", "async_cancel_goal", "async_get_result")
THREADS = ("thread", "jthread", "async", "create_thread")
DEFINITIONS = (K.FUNCTION_DECL, K.CXX_METHOD, K.CONSTRUCTOR, K.DESTRUCTOR, K.FUNCTION_TEMPLATE)
FUNCTIONS = (K.FUNCTION_DECL, K.CXX_METHOD, K.FUNCTION_TEMPLATE)
ACCESSORS = ("operator->", "operator*", "operator[]", "at", "get", "back", "front", "second", "first")


class Host(Protocol):
    """What the walker (roscpp._Walker) gives behavior: ids and shown files of cursors, values,
    and the file's calls by callee."""

    file: str
    source: str
    call_sites: dict[CursorKey, list[ci.Cursor]]

    def key(self, decl: ci.Cursor | None) -> CursorKey: ...
    def shown(self, cursor: ci.Cursor) -> str: ...
    def workspace_code(self, decl: ci.Cursor) -> bool: ...
    def value(self, expr: ci.Cursor, depth: int = 0) -> Value: ...
    def seconds(self, expr: ci.Cursor, depth: int = 0) -> Fraction | None: ...
    def unknown(self, cursor: ci.Cursor, why: str = "") -> Unknown: ...


@dataclass
class Function:
    """A function definition or lambda of the file (or of a workspace header it uses)."""

    id: CursorKey
    cursor: ci.Cursor
    file: str
    start: int
    end: int


@dataclass
class Store:
    """A write: `target` gets `value` (an assignment, a member initializer), or is changed by
    `op` (a method such as push_back, "ref" when passed by reference, "?" for ++ and +=, "port"
    for a port made on it: `sub.subscribe(...)`)."""

    target: ci.Cursor
    value: ci.Cursor | None
    op: str
    at: ci.Cursor


@dataclass
class FileIndex:
    """The file's functions, calls and writes, read in one pass (`read`)."""

    key: Callable[[ci.Cursor | None], tuple | None]
    port_calls: Collection[ci.Cursor]
    functions: list[Function] = field(default_factory=list)
    by_id: dict[CursorKey, Function] = field(default_factory=dict)
    publishes: list[ci.Cursor] = field(default_factory=list)
    stores: list[Store] = field(default_factory=list)
    flows: dict[CursorKey, list[ci.Cursor]] = field(default_factory=dict)  # variable -> what is stored in it
    registrations: list[ci.Cursor] = field(default_factory=list)
    handoffs: list[ci.Cursor] = field(default_factory=list)
    invocations: list[ci.Cursor] = field(default_factory=list)  # f() on a variable holding a lambda
    lambdas: list[ci.Cursor] = field(default_factory=list)
    calls: list[ci.Cursor] = field(default_factory=list)  # calls of functions and methods

    def read(self, cursors: list[ci.Cursor]) -> None:
        for cursor in cursors:
            kind = cursor.kind
            if kind == K.CALL_EXPR:
                self.call(cursor)
            elif kind in (K.BINARY_OPERATOR, K.COMPOUND_ASSIGNMENT_OPERATOR, K.UNARY_OPERATOR):
                self.operator(cursor, kind)
            elif kind == K.LAMBDA_EXPR:
                self.lambdas.append(cursor)
                self.functions.append(_function(self.lambda_id(cursor), cursor))
            elif kind in DEFINITIONS and cursor.is_definition():
                self.functions.append(_function(self.key(cursor.canonical), cursor))
                if kind == K.CONSTRUCTOR:
                    children = list(cursor.get_children())
                    for member, init in zip(children, children[1:]):
                        if member.kind == K.MEMBER_REF:
                            self.store(member, init, "=", member)
            elif kind == K.VAR_DECL:
                init = [c for c in cursor.get_children() if c.kind not in SKIP]
                if init:
                    self.flows.setdefault(self.key(cursor), []).append(init[-1])
        self.by_id = {f.id: f for f in self.functions}

    def call(self, call: ci.Cursor) -> None:
        name = call.spelling
        if name in PUBLISH_CALLS:
            owner = qualified(call.referenced.semantic_parent) if call.referenced is not None else ""
            if owner in PUBLISH_CALLS[name]:
                self.publishes.append(call)
        if name == "operator=" and len(parts := operands(call)) == 2:
            self.store(parts[0], parts[1], "=", call)
        elif name in CONTAINER_WRITES or name in POINTER_WRITES:
            obj = object_of(call)
            if obj is not None:
                args = written_args(call)
                self.store(obj, args[0] if args else None, name, call)
        elif name in DEFERRED or name in THREADS:
            self.handoffs.append(call)
        elif name == "operator()":
            self.invocations.append(call)
        elif REGISTRATION.search(name) and call not in self.port_calls:
            self.registrations.append(call)
        if call in self.port_calls and (obj := object_of(call)) is not None:
            self.store(obj, call, "port", call)
        if call.referenced is not None and call.referenced.kind in FUNCTIONS:
            self.calls.append(call)
        self.by_reference(call)

    def by_reference(self, call: ci.Cursor) -> None:
        """Members and globals passed by non-const reference (param(name, member_, default),
        fromROSMsg(msg, cloud_)) may be changed: a write of an unknown value."""
        ref = call.referenced
        if ref is None or ref.kind not in (*FUNCTIONS, K.CONSTRUCTOR):
            return
        args = list(call.get_arguments())
        candidates = [(i, a) for i, a in enumerate(args) if strip(a).kind in (K.MEMBER_REF_EXPR, K.DECL_REF_EXPR)]
        params = [c for c in ref.get_children() if c.kind == K.PARM_DECL] if candidates else []
        for index, arg in candidates:
            if index < len(params):
                type_ = params[index].type
                if type_.kind == ci.TypeKind.LVALUEREFERENCE and not type_.get_pointee().is_const_qualified():
                    self.store(arg, None, "ref", call)

    def operator(self, expr: ci.Cursor, kind: ci.CursorKind) -> None:
        if kind == K.UNARY_OPERATOR:
            if unary_operator(expr) in ("++", "--"):
                self.store(next(expr.get_children()), None, "?", expr)
            return
        op = binary_operator(expr)
        if op == "=" or kind == K.COMPOUND_ASSIGNMENT_OPERATOR:
            children = list(expr.get_children())
            if len(children) == 2:
                self.store(children[0], children[1] if op == "=" else None, "=" if op == "=" else "?", expr)

    def store(self, target: ci.Cursor, value: ci.Cursor | None, op: str, at: ci.Cursor) -> None:
        self.stores.append(Store(target, value, op, at))
        decl = root_decl(target)
        if decl is not None and value is not None:
            self.flows.setdefault(self.key(decl), []).append(value)

    def lambda_id(self, lam: ci.Cursor) -> tuple:
        """A lambda's id (apart from the ids of its class's members, which share its location)."""
        return ("lambda", *(self.key(lam) or ()))

    def enclosing(self, cursor: ci.Cursor) -> Function | None:
        """The innermost function or lambda holding a cursor (other than the cursor itself)."""
        extent = cursor.extent
        return self.enclosing_offset(extent.start.file.name if extent.start.file is not None else "",
                                     extent.start.offset, extent.end.offset)

    def enclosing_offset(self, file: str, start: int, end: int | None = None) -> Function | None:
        """The innermost function or lambda holding a range of a file (other than that range)."""
        end = start if end is None else end
        best: Function | None = None
        for function in self.functions:
            if function.start <= start and end <= function.end and (function.start, function.end) != (start, end) \
                    and function.file == file and (best is None or function.start >= best.start):
                best = function
        return best


def root_decl(expr: ci.Cursor) -> ci.Cursor | None:
    """The variable an lvalue is part of: `pubs_` in `pubs_[name]`, `*pub`, `pub->...`."""
    expr = strip(expr)
    for _ in range(8):
        if expr.kind == K.CALL_EXPR and expr.spelling in ACCESSORS:
            inner = object_of(expr) or next(iter(operands(expr)), None)
            if inner is None:
                return None
            expr = strip(inner)
        elif expr.kind == K.ARRAY_SUBSCRIPT_EXPR or (expr.kind == K.UNARY_OPERATOR and unary_operator(expr) == "*"):
            expr = strip(next(expr.get_children()))
        else:
            break
    if expr.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR, K.MEMBER_REF):
        return expr.referenced
    return None


def _function(fid: CursorKey, cursor: ci.Cursor) -> Function:
    extent = cursor.extent
    return Function(fid, cursor, extent.start.file.name if extent.start.file is not None else "",
                    extent.start.offset, extent.end.offset)
