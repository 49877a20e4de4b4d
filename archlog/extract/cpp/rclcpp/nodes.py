"""The nodes a file creates: their names and namespaces, and the sub-nodes of create_sub_node()."""

from __future__ import annotations

import clang.cindex as ci

from archlog.diagnostics import Diagnostic
from archlog.extract.cpp.clang_ast import CursorKey, K, qualified, written_args
from archlog.extract.cpp.rclcpp.api import LIFECYCLE_NODE, NODE_CLASSES, object_of, parameter_names
from archlog.extract.cpp.rclcpp.context import WalkContext
from archlog.extract.cpp.rclcpp.definitions import Definitions
from archlog.values import Value, concat

# rclcpp::NodeOptions setters that add (True) or remove (False) a group of built-in ports:
# setter -> (group, adds); the groups are models/infrastructure/ros2.yaml's
_NODE_OPTIONS = {"enable_logger_service": ("logger_service", True),
                 "start_parameter_services": ("parameter_services", False), "enable_rosout": ("rosout", False),
                 "start_parameter_event_publisher": ("parameter_events", False)}


class Nodes:
    """Reads node constructions (the file's node name) and the namespaces of sub-nodes."""

    def __init__(self, ctx: WalkContext, definitions: Definitions) -> None:
        self.ctx, self.definitions = ctx, definitions
        self.sub_nodes: dict[CursorKey, ci.Cursor] = {}
        self.node_names: list[Value] = []

    def node_ns(self, expr: ci.Cursor | None, depth: int = 0) -> Value:
        """The namespace an entity created on this node gets: "" for the node itself, the
        sub-namespace for a node made by create_sub_node()."""
        if expr is None or depth > 4:
            return ""
        for cursor in expr.walk_preorder():
            if cursor.kind == K.CALL_EXPR and cursor.spelling == "create_sub_node" and written_args(cursor):
                parent = self.node_ns(object_of(cursor), depth + 1)
                sub = self.ctx.value(written_args(cursor)[0])
                return concat(parent, "/", sub) if parent else sub
            if cursor.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and cursor.referenced is not None:
                sub_call = self.sub_nodes.get(self.ctx.key(cursor.referenced))
                return self.node_ns(sub_call, depth + 1) if sub_call is not None else ""
        return ""

    def _options(self, args: list[ci.Cursor]) -> None:
        """The built-in port groups the node's NodeOptions turn on or off (`enable_logger_service(true)`,
        `start_parameter_services(false)`, `enable_rosout(false)`, `start_parameter_event_publisher(false)`),
        written in its constructor's arguments."""
        for arg in args:
            for call in arg.walk_preorder():
                flag = _NODE_OPTIONS.get(call.spelling) if call.kind == K.CALL_EXPR else None
                if flag is None or len(written_args(call)) != 1:
                    continue
                group, adds = flag
                value = str(self.ctx.value(written_args(call)[0])).lower()
                result = self.ctx.result
                if adds and value == "true":
                    result.infrastructure = tuple(dict.fromkeys([*result.infrastructure, group]))
                elif not adds and value == "false":
                    result.without = tuple(dict.fromkeys([*result.without, group]))

    def node_constructed(self, call: ci.Cursor, args: list[ci.Cursor], ctor: ci.Cursor | None) -> None:
        """A node's name and namespace from its constructor: rclcpp::Node("name", "ns", options),
        a subclass's base initializer, std::make_shared<rclcpp::Node>(...), Node::make_shared(...)."""
        names = parameter_names(ctor) if ctor is not None else ["node_name", "namespace_"]
        if ctor is not None and qualified(ctor.semantic_parent) not in NODE_CLASSES and \
                not self.definitions.base_init(call):
            return  # a subclass constructed in this file: its own base initializer names it
        texts = [(n, a) for n, a in zip(names, args) if "string" in a.type.get_canonical().spelling
                 or "char" in a.type.spelling]
        name = next((a for n, a in texts if n in ("node_name", "name")), texts[0][1] if texts else None)
        if name is None:
            return
        if ctor is not None and qualified(ctor.semantic_parent) == LIFECYCLE_NODE:
            self.ctx.result.infrastructure = tuple(dict.fromkeys([*self.ctx.result.infrastructure, "lifecycle"]))
        self._options(args)
        value = self.ctx.value(name)
        namespace = next((a for n, a in texts if n in ("namespace_", "namespace", "ns", "node_namespace")), None)
        if self.node_names and value not in self.node_names:
            self.ctx.result.diagnostics.append(Diagnostic(
                self.ctx.shown(call), call.location.line, "cpp-several-nodes", f"this file creates several nodes "
                f"({self.node_names[0]}, {value}); archlog reads them as one node named after the first", "note"))
            self.ctx.result.params_dynamic = self.ctx.result.params_dynamic or \
                f"{self.ctx.shown(call)}:{call.location.line}: the file creates several nodes, read as one: which " \
                "parameters each declares is not known"
        self.node_names.append(value)
        if self.ctx.result.default_name is None:
            self.ctx.result.default_name = value
            self.ctx.result.namespace = self.ctx.value(namespace) if namespace is not None else ""
            self.ctx.result.name_file, self.ctx.result.name_line = self.ctx.shown(call), call.location.line
