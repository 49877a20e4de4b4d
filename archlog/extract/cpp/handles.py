"""roscpp's handles (NodeHandle, ImageTransport): the ports their methods create, and the
namespace each handle of a file gives its ports."""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

import clang.cindex as ci

from archlog import names
from archlog.extract.cpp.clang_ast import CursorKey, K, written_args
from archlog.values import Unknown, Value, concat

NODE_HANDLE = "ros::NodeHandle"
IMAGE_TRANSPORT = "image_transport::ImageTransport"
IMAGE_FILTER = "image_transport::SubscriberFilter"  # a message_filters input of images, on an ImageTransport
HANDLE_TYPES = (NODE_HANDLE, IMAGE_TRANSPORT)
# (class, method) -> port kind
NODELET_LAZY = "nodelet_topic_tools::NodeletLazy"
METHODS = {
    (NODE_HANDLE, "advertise"): "publisher", (NODE_HANDLE, "subscribe"): "subscriber",
    (NODE_HANDLE, "advertiseService"): "service_server", (NODE_HANDLE, "serviceClient"): "service_client",
    (IMAGE_TRANSPORT, "advertise"): "publisher", (IMAGE_TRANSPORT, "subscribe"): "subscriber",
    (IMAGE_TRANSPORT, "advertiseCamera"): "publisher", (IMAGE_TRANSPORT, "subscribeCamera"): "subscriber",
    ("message_filters::Subscriber", "subscribe"): "subscriber", (IMAGE_FILTER, "subscribe"): "subscriber",
    (NODELET_LAZY, "advertise"): "publisher",  # advertise<T>(nh, topic, queue): a lazy nodelet's publisher
}
# nodelet::Nodelet accessors for the manager-provided handles
NODELET_HANDLES = {"getNodeHandle": "", "getMTNodeHandle": "", "getPrivateNodeHandle": "~",
                   "getMTPrivateNodeHandle": "~"}


def is_handle_type(type_: ci.Type) -> bool:
    """A NodeHandle or an ImageTransport (or a pointer or reference to one)."""
    spelling = type_.spelling
    return "NodeHandle" in spelling or "ImageTransport" in spelling


class HandleContext(Protocol):
    """What reading handles needs of the walker: keys and values of cursors, and the value all
    call sites of a function agree on for a parameter."""

    kept: list[ci.Cursor]

    def key(self, decl: ci.Cursor | None) -> CursorKey: ...
    def value(self, expr: ci.Cursor, depth: int = 0) -> Value: ...
    def unknown(self, cursor: ci.Cursor, why: str = "") -> Unknown: ...
    def from_call_sites(self, param: ci.Cursor, expr: ci.Cursor, evaluate: Callable[[ci.Cursor], Value],
                        what: str) -> Value: ...


class Handles:
    """The namespaces of a file's handles, by declaration, read as they are met."""

    def __init__(self, ctx: HandleContext) -> None:
        self.ctx = ctx
        self.namespaces: dict[CursorKey, Value] = {}

    def handle_ns(self, decl: ci.Cursor) -> Value:
        getter = next((c.spelling for c in decl.walk_preorder() if c.kind == K.CALL_EXPR
                       and c.spelling in NODELET_HANDLES), None) or _accessor_assigned(decl)
        if getter:
            return NODELET_HANDLES[getter]
        ctor = next((c for c in decl.get_children() if c.kind in (K.CALL_EXPR, K.UNEXPOSED_EXPR)), None)
        return self.ctor_ns(ctor) if ctor is not None else ""

    def ctor_ns(self, ctor: ci.Cursor) -> Value:
        """The namespace of a NodeHandle (or ImageTransport) built by this constructor call."""
        while ctor.kind == K.UNEXPOSED_EXPR and len(list(ctor.get_children())) == 1:
            ctor = next(ctor.get_children())
        args = written_args(ctor) if ctor.kind == K.CALL_EXPR else []
        if not args:
            return ""
        first_is_handle = is_handle_type(args[0].type)
        parent = self.handle_of(args[0]) if first_is_handle else ""
        if first_is_handle and len(args) == 1:
            return parent
        ns = self.ctx.value(args[1] if first_is_handle else args[0])
        if not isinstance(ns, str) or not isinstance(parent, str):
            return concat(parent, "/", ns) if parent else ns
        if ns.startswith("/") or not parent:
            return ns
        return f"~{ns}" if parent == "~" else names.canonical(f"{parent}/{ns}")

    def reset_ns(self, field: ci.Cursor, depth: int) -> Value:
        """A handle member (or a smart pointer to one) that the code read sets, `field = getPrivate
        NodeHandle()` or `field.reset(new ros::NodeHandle(...))` (also in the inline methods of its
        class, as nodelet_topic_tools::NodeletLazy's pnh_ in a header not otherwise read): the
        namespace they agree on; if none sets it, that of its initializer in the class, else the node's."""
        found: set[Value] = set()
        inline = list(field.semantic_parent.walk_preorder()) if field.semantic_parent is not None else []
        for call in inline + self.ctx.kept:
            if call.kind != K.CALL_EXPR or call.spelling not in ("reset", "operator="):
                continue
            parts = list(call.get_children())
            if len(parts) < 2 or not any(c.referenced == field for c in parts[0].walk_preorder()
                                         if c.kind == K.MEMBER_REF_EXPR):
                continue
            found.add(self.handle_of(parts[-1], depth + 1))
        if not found:
            return self.handle_ns(field)  # its initializer in the class (`ros::NodeHandle pnh_{"~"}`), if any
        return found.pop() if len(found) == 1 and not isinstance(next(iter(found)), Unknown) else ""

    def member_inits(self, ctor: ci.Cursor) -> None:
        children = list(ctor.get_children())
        for member, init in zip(children, children[1:]):
            if member.kind == K.MEMBER_REF and is_handle_type(member.type):
                self.namespaces[self.ctx.key(member.referenced)] = self.ctor_ns(init)

    def handle_of(self, expr: ci.Cursor, depth: int = 0) -> Value:
        """The namespace of the NodeHandle an expression refers to."""
        for cursor in expr.walk_preorder():
            if cursor.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and is_handle_type(cursor.type):
                decl = cursor.referenced
                key = self.ctx.key(decl)
                if key not in self.namespaces and decl is not None and decl.kind == K.VAR_DECL:
                    self.namespaces[key] = self.handle_ns(decl)
                if key in self.namespaces:
                    return self.namespaces[key]
                if decl is not None and decl.kind == K.FIELD_DECL and depth < 4:
                    self.namespaces[key] = ""  # while it is looked for
                    self.namespaces[key] = self.reset_ns(decl, depth)
                    return self.namespaces[key]
                if decl is not None and decl.kind == K.FIELD_DECL:
                    return ""
                if decl is not None and decl.kind == K.PARM_DECL and depth < 4:
                    return self.ctx.from_call_sites(decl, expr, lambda arg: self.handle_of(arg, depth + 1),
                                                    "NodeHandle")
                break
            if cursor.kind == K.CALL_EXPR and is_handle_type(cursor.type):
                if cursor.spelling in NODELET_HANDLES:
                    return NODELET_HANDLES[cursor.spelling]
                if cursor.spelling in ("NodeHandle", "ImageTransport"):
                    return self.ctor_ns(cursor)
        return self.ctx.unknown(expr, "NodeHandle of unknown origin")


def _accessor_assigned(decl: ci.Cursor) -> str | None:
    """The nodelet accessor a declaration is initialised with (`NodeHandle& nh = this->getPrivateNodeHandle()`),
    read from its tokens: libclang leaves the call unresolved when it is dependent (a class template)
    or when the nodelet's headers are missing."""
    tokens = [t.spelling for t in decl.get_tokens()]
    rest = tokens[tokens.index("=") + 1:] if "=" in tokens else []
    rest = rest[2:] if rest[:2] == ["this", "->"] else rest
    return rest[0] if rest[1:3] == ["(", ")"] and rest[0] in NODELET_HANDLES else None
