"""The rclcpp (ROS 2) reader of the C++ walker: nodes and their names, publishers, subscriptions,
services, clients, actions, parameters, timers, tf2_ros, image_transport, message_filters and
diagnostic_updater, with the QoS of every publisher and subscription.

Calls are recognised by the qualified name of what they call (`rclcpp::Node::create_publisher`),
so the real headers and archlog's stand-ins (cpp/stubs.py) give the same result.
"""

from __future__ import annotations

from dataclasses import replace

import clang.cindex as ci

from archlog.extract.cpp.callers import FromCaller
from archlog.extract.cpp.clang_ast import (
    SKIP,
    CursorKey,
    K,
    camera_info,
    qualified,
    ros2_type,
    ros_type,
    strip,
    type_from_spelling,
    written_args,
)
from archlog.extract.cpp.rclcpp.api import (
    ENTITIES,
    FACTORIES,
    FREE_FUNCTIONS,
    IMAGE_TRANSPORT_METHODS,
    NAME_PARAMETERS,
    NODE_CLASSES,
    PARAMETER_READS,
    PARAMETER_WRITES,
    QOS_PARAMETERS,
    default_argument,
    factory_class,
    node_class,
    node_method,
    object_of,
    parameter_helper,
    parameter_names,
    sub_node_call,
    tokens,
)
from archlog.extract.cpp.rclcpp.context import WalkContext
from archlog.extract.cpp.rclcpp.definitions import Definitions
from archlog.extract.cpp.rclcpp.durations import Durations
from archlog.extract.cpp.rclcpp.nodes import Nodes
from archlog.extract.cpp.rclcpp.parameters import Parameters
from archlog.extract.cpp.rclcpp.qos import QosReader, builtin_qos
from archlog.extract.cpp.rclcpp.qos_changes import QosChanges
from archlog.extract.cpp.rclcpp.wrappers import Summaries, Wrapper, written_wrappers
from archlog.extract.qos import Qos, number, seconds_text
from archlog.extract.summary import Port
from archlog.values import Value

# classes whose construction creates ports: (kind, topic, type, the library's QoS: rclcpp::QoS(depth)
# with these policies changed)
TF2 = {
    "tf2_ros::TransformBroadcaster": [("publisher", "/tf", "tf2_msgs/msg/TFMessage", Qos({"depth": "100"}))],
    "tf2_ros::StaticTransformBroadcaster": [("publisher", "/tf_static", "tf2_msgs/msg/TFMessage",
                                             Qos({"depth": "1", "durability": "transient_local"}))],
    "tf2_ros::TransformListener": [("subscriber", "/tf", "tf2_msgs/msg/TFMessage", Qos({"depth": "100"})),
                                   ("subscriber", "/tf_static", "tf2_msgs/msg/TFMessage",
                                    Qos({"depth": "100", "durability": "transient_local"}))],
    "diagnostic_updater::Updater": [("publisher", "/diagnostics", "diagnostic_msgs/msg/DiagnosticArray",
                                     Qos({"depth": "1"}))],
}
CONSTRUCTED_ROS2 = {*TF2, "message_filters::Subscriber"}


def _callees(call: ci.Cursor) -> list[ci.Cursor]:
    """The definitions a call may run: its function's, or for make_shared<T> T's constructors."""
    ref = call.referenced
    if ref is None:
        return []
    if call.spelling in FACTORIES and (cls := factory_class(call)) is not None:
        return [c.get_definition() or c for c in cls.get_children() if c.kind in (K.CONSTRUCTOR, K.FUNCTION_TEMPLATE)]
    return [ref.get_definition() or ref]


def _also_if(port: Port, base: Port) -> Port:
    """A wrapper's port at its call site, under the conditions of the wrapper's own call as well."""
    conditions = [c for c in (port.condition, *port.also, base.condition, *base.also) if c is not None]
    return replace(port, condition=conditions[0], also=tuple(conditions[1:]))


class RclcppWalker:
    """Reads the ROS 2 calls of one file for the walker `ctx`: prepare() once over the file's
    cursors, then call() for each call and value() for the values of rclcpp calls."""

    def __init__(self, ctx: WalkContext, durations: Durations) -> None:
        self.ctx, self.durations = ctx, durations
        self.definitions = Definitions()
        self.changes = QosChanges(ctx)
        self.nodes = Nodes(ctx, self.definitions)
        self.parameters = Parameters(ctx)
        self.qos = QosReader(ctx, durations, self.changes, self.definitions)

    def prepare(self, cursors: list[ci.Cursor]) -> None:
        """What later calls need to know about the whole file: parameter declarations (their
        defaults), sub-nodes, QoS mutations, and make_shared calls as call sites of the
        constructors they call."""
        self.definitions.read(cursors)
        for cursor in cursors:
            if cursor.kind == K.CALL_EXPR and cursor.referenced is not None:
                self.prepare_call(cursor)
            elif cursor.kind in (K.CONSTRUCTOR, K.CXX_METHOD, K.FUNCTION_DECL, K.LAMBDA_EXPR) and \
                    (cursor.kind == K.LAMBDA_EXPR or cursor.is_definition()):
                body = next((c for c in cursor.get_children() if c.kind == K.COMPOUND_STMT), None)
                if body is not None:
                    self.changes.statements(body, False)
            elif cursor.kind in (K.VAR_DECL, K.FIELD_DECL):
                init = [c for c in cursor.get_children() if c.kind not in SKIP]
                if init and (sub := sub_node_call(init[-1])) is not None:
                    self.nodes.sub_nodes[self.ctx.key(cursor)] = sub

    def prepare_call(self, call: ci.Cursor) -> None:
        args = written_args(call)
        if self.parameters.prepare_call(call, args):
            return
        if call.spelling == "operator=" and len(args) == 2 and (sub := sub_node_call(args[1])) is not None:
            target = strip(args[0])
            if target.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR):
                self.nodes.sub_nodes[self.ctx.key(target.referenced)] = sub
        elif call.spelling in FACTORIES and (cls := factory_class(call)) is not None:
            for ctor in cls.get_children():
                if ctor.kind == K.CONSTRUCTOR:
                    self.ctx.call_sites.setdefault(self.ctx.key(ctor.canonical), []).append(call)

    def call(self, call: ci.Cursor, ref: ci.Cursor, owner: str, name: str, args: list[ci.Cursor]) -> bool:
        """Read one call if it is ROS 2 API; True when it was."""
        if ref.kind == K.CONSTRUCTOR and node_class(ref.semantic_parent):
            self.nodes.node_constructed(call, args, ref)
        elif name in FACTORIES:
            cls = factory_class(call)
            if cls is not None and qualified(cls) in NODE_CLASSES:
                self.nodes.node_constructed(call, args, None)
            elif cls is not None and qualified(cls) in CONSTRUCTED_ROS2:
                self.constructed_ros2(call, qualified(cls), args, cls)
            else:
                return False
        elif ref.kind == K.CONSTRUCTOR and owner in CONSTRUCTED_ROS2:
            self.constructed_ros2(call, owner, args, ref.semantic_parent)
        elif name in ENTITIES and node_method(ref, owner):
            self.entity(call, ref, ENTITIES[name], args, self.nodes.node_ns(object_of(call)), name)
        elif (owner, name) in FREE_FUNCTIONS and args:
            self.entity(call, ref, FREE_FUNCTIONS[(owner, name)], args, self.nodes.node_ns(args[0]), name)
        elif owner == "image_transport::ImageTransport" and name in IMAGE_TRANSPORT_METHODS and args:
            self.entity(call, ref, IMAGE_TRANSPORT_METHODS[name], args, "", name)
        elif owner == "message_filters::Subscriber" and name == "subscribe" and len(args) > 1:
            self.constructed_ros2(call, owner, args, ref.semantic_parent)
        elif owner in NODE_CLASSES and name in PARAMETER_READS and args:
            self.parameters.read(call, name, args)
        elif self.parameters.dynamic(call, owner, name, args):
            pass
        elif (helper := parameter_helper(ref)) is not None and helper[0] < len(args):
            self.parameters.helper_read(call, helper, args)
        elif owner in NODE_CLASSES and name in PARAMETER_WRITES and args:
            self.parameters.write(call, args)
        elif name in ("create_wall_timer", "create_timer") and (node_method(ref, owner) or owner == "rclcpp") and \
                "period" in (params := parameter_names(ref)) and params.index("period") < len(args):
            self.ctx.add("timer", call, self.durations.period(args[params.index("period")]), "", "")
        elif ref.kind == K.CONSTRUCTOR and owner in ("rclcpp::Rate", "rclcpp::WallRate", "rclcpp::GenericRate") \
                and args:
            rate = self.ctx.value(args[0])
            hz = number(rate) if isinstance(rate, str) else None
            period = seconds_text(1 / hz) if hz else self.durations.period(args[0])
            self.ctx.add("timer", call, period or self.ctx.unknown(call, "rate not constant"), "", "")
        else:
            return False
        return True

    def wrapped(self, summaries: Summaries, calls: list[ci.Cursor], bound: dict[str, str]) -> None:
        """One port at each call of a function that creates a port named by its argument
        (wrappers.py), with the name that call passes; the port of the wrapper's own rclcpp call,
        whose name no single call decides, is left out then. A call inside a template is matched by
        its tokens; a template parameter it passes as the interface is read as `bound` binds it
        (the class read alone derives from the template with that argument)."""
        wrappers = summaries.wrappers
        made = {(p.file, p.line, p.kind): p for p in self.ctx.result.ports}
        bases: set[tuple[str, int, str]] = set()
        for call in dict.fromkeys(calls):  # each call once
            args = written_args(call)
            found: dict[tuple[int, str, str | None], list[tuple[str, int, str]]] = {}
            runs = [(w, w.type_) for callee in _callees(call) for w in wrappers.get(self.ctx.key(callee), ())] \
                if call.referenced is not None else \
                [(w, bound.get(t, t) if t else None) for w, t in written_wrappers(call, summaries)]
            for w, written in runs:  # one port, whatever the ways to its rclcpp call
                if w.index < len(args) and not self.passed_on(args[w.index], wrappers, w.kind):
                    found.setdefault((w.index, w.kind, written), []).append((*w.base, w.kind))
            chosen = {(index, kind) for index, kind, _written in found}
            for (index, kind, written), inner in found.items():
                bases.update(inner)
                if (self.ctx.shown(call), call.location.line, kind) in made or (index, kind) not in chosen:
                    continue  # read as rclcpp's own call, or made below with the other types
                chosen.discard((index, kind))
                base = next((made[b] for b in inner if b in made), None)  # the rclcpp call as the AST read it
                type_: Value | None = (type_from_spelling(written) if written else
                                       self.entity_type(call) if call.referenced is not None else None) or \
                    (base.type if base is not None and isinstance(base.type, str) else None)
                types = sorted({t for i, k, t in found if (i, k) == (index, kind)}, key=str)
                if len(types) > 1:  # the wrapper picks one in a branch archlog does not decide
                    type_ = self.ctx.unknown(call, f"one of {', '.join(str(t) for t in types)}, as the callee decides")
                self.ctx.add(kind, call, self.ctx.value(args[index]),
                             type_ or self.ctx.unknown(call, "message type not resolved"),
                             base.handle_ns if base is not None else "", qos=base.qos if base is not None else ())
                if base is not None and base.condition is not None:  # the branch the wrapper creates it in
                    self.ctx.result.ports[-1] = _also_if(self.ctx.result.ports[-1], base)
        self.ctx.result.ports = [p for p in self.ctx.result.ports if (p.file, p.line, p.kind) not in bases or
                                 isinstance(p.name, FromCaller)]

    def passed_on(self, arg: ci.Cursor, wrappers: dict[CursorKey, set[Wrapper]], kind: str) -> bool:
        """The argument is a parameter of a wrapper that names the same kind of port with it: that
        wrapper's callers give the name."""
        decl = strip(arg).referenced
        if decl is None or decl.kind != K.PARM_DECL or decl.semantic_parent is None:
            return False
        function = decl.semantic_parent
        index = parameter_names(function).index(decl.spelling) if decl.spelling in parameter_names(function) else -1
        return any(w.index == index and w.kind == kind for w in wrappers.get(self.ctx.key(function), ()))

    def value(self, expr: ci.Cursor, owner: str, name: str, args: list[ci.Cursor], depth: int) -> Value | None:
        """The value of an rclcpp call (a parameter read, get_name()...), None when it is not one."""
        return self.parameters.call_value(expr, owner, name, args, depth)

    def entity(self, call: ci.Cursor, ref: ci.Cursor, kind: str, args: list[ci.Cursor], handle: Value,
               method: str) -> None:
        """A publisher, subscription, service, client or action server/client."""
        params = parameter_names(ref)
        position = next((params.index(p) for p in NAME_PARAMETERS if p in params), 0)
        if position >= len(args):
            return
        topic = self.ctx.value(args[position])
        if method.startswith("create_generic"):
            type_: Value = self.ctx.value(args[position + 1]) if len(args) > position + 1 else \
                self.ctx.unknown(call, "type not given")
        elif "image_transport" in qualified(ref.semantic_parent) or method in IMAGE_TRANSPORT_METHODS:
            type_ = "sensor_msgs/msg/Image"
        else:
            type_ = self.entity_type(call) or self.ctx.unknown(call, "message type not resolved")
        qos: tuple[tuple[str, str], ...] = ()
        if kind in ("publisher", "subscriber"):
            at = next((params.index(p) for p in QOS_PARAMETERS if p in params), -1)
            given = args[at] if 0 <= at < len(args) else default_argument(ref, at) if at >= 0 else None
            default = "default" if "image_transport" in qualified(ref.semantic_parent) else None
            qos = self.qos.facts(given, call, default)
        self.ctx.add(kind, call, topic, type_, handle, qos=qos)
        if method.endswith(("Camera", "camera_publisher", "camera_subscription")):
            self.ctx.add(kind, call, camera_info(topic), "sensor_msgs/msg/CameraInfo", handle, qos=qos)

    def entity_type(self, call: ci.Cursor) -> str | None:
        """The interface type: the call's template argument, else its result type
        (std::shared_ptr<rclcpp::Publisher<std_msgs::msg::String_<...>>>), else its tokens."""
        ref = call.referenced
        if ref.get_num_template_arguments() > 0 and (found := ros_type(ref.get_template_argument_type(0))):
            return found
        return ros2_type(call.type.get_canonical().spelling) or \
            type_from_spelling(tokens(call).split("(", 1)[0].replace(" ", ""))

    def constructed_ros2(self, call: ci.Cursor, owner: str, args: list[ci.Cursor], cls: ci.Cursor) -> None:
        """tf2_ros broadcasters and listeners, diagnostic_updater, message_filters::Subscriber."""
        if owner == "message_filters::Subscriber":
            if len(args) < 2:
                return  # default-constructed: the port comes from a later subscribe()
            type_ = ros2_type(call.type.get_canonical().spelling) or ros_type(cls.type) or \
                self.ctx.unknown(call, "message type not resolved")
            self.ctx.add("subscriber", call, self.ctx.value(args[1]), type_, self.nodes.node_ns(args[0]),
                     qos=self.qos.facts(args[2] if len(args) > 2 else None, call, "default"))
            return
        params = parameter_names(call.referenced) if call.referenced.kind == K.CONSTRUCTOR else []
        given = next((args[params.index("qos")] for _ in [0] if "qos" in params and params.index("qos") < len(args)),
                     None)
        for kind, topic, type_, qos in TF2[owner]:
            facts = self.qos.facts(given, call) if given is not None and owner != "tf2_ros::TransformListener" else \
                builtin_qos(qos)
            self.ctx.add(kind, call, topic, type_, "", qos=facts)
