"""The rclcpp (ROS 2) part of the C++ walker: nodes and their names, publishers, subscriptions,
services, clients, actions, parameters, timers, tf2_ros, image_transport, message_filters and
diagnostic_updater, with the QoS of every publisher and subscription.

Calls are recognised by the qualified name of what they call (`rclcpp::Node::create_publisher`),
so the real headers and archlog's stand-ins (ros2_stubs.py) give the same result. Parameters are
node-private in ROS 2: their ports and the values read from them have the handle "~".
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction

import clang.cindex as ci

from archlog import sandbox
from archlog.diagnostics import Diagnostic
from archlog.extract.cpp.ast import (
    CALL_WINDOW,
    SKIP,
    K,
    binary_operator,
    camera_info,
    line_finder,
    qualified,
    ros2_type,
    ros_type,
    type_from_spelling,
    unquote,
    written_args,
)
from archlog.extract.cpp.cache import cache_dir
from archlog.extract.cpp.stubs import API_DIR
from archlog.extract.qos import FIXED_SETTERS, PRESET_NAMES, Qos, number, seconds_text
from archlog.extract.summary import Port
from archlog.values import ParamRef, Unknown, Value, concat

NODE_CLASSES = ("rclcpp::Node", "rclcpp_lifecycle::LifecycleNode")
# Node methods (and free functions of the same name) -> port kind
ENTITIES = {"create_publisher": "publisher", "create_subscription": "subscriber", "create_service": "service_server",
            "create_client": "service_client", "create_generic_publisher": "publisher",
            "create_generic_subscription": "subscriber"}
FREE_FUNCTIONS = {
    ("rclcpp", "create_publisher"): "publisher", ("rclcpp", "create_subscription"): "subscriber",
    ("rclcpp", "create_service"): "service_server", ("rclcpp", "create_client"): "service_client",
    ("rclcpp_action", "create_server"): "action_server", ("rclcpp_action", "create_client"): "action_client",
    ("image_transport", "create_publisher"): "publisher", ("image_transport", "create_subscription"): "subscriber",
    ("image_transport", "create_camera_publisher"): "publisher",
    ("image_transport", "create_camera_subscription"): "subscriber",
}
IMAGE_TRANSPORT_METHODS = {"advertise": "publisher", "subscribe": "subscriber", "advertiseCamera": "publisher",
                           "subscribeCamera": "subscriber"}
PARAMETER_READS = ("declare_parameter", "get_parameter", "get_parameter_or")
PARAMETER_WRITES = ("set_parameter", "set_parameters", "set_parameters_atomically")
# parameter names of the API that hold a port's name and its QoS
NAME_PARAMETERS = ("topic_name", "service_name", "name", "base_topic", "topic")
QOS_PARAMETERS = ("qos", "qos_profile", "custom_qos", "queue_size")
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
FACTORIES = {"make_shared", "make_unique", "allocate_shared"}
_CHRONO_LITERAL = re.compile(r"^(\d+(?:\.\d*)?|\.\d+)(h|min|s|ms|us|ns)$")
_CHRONO_UNITS = {"h": Fraction(3600), "min": Fraction(60), "s": Fraction(1), "ms": Fraction(1, 1000),
                 "us": Fraction(1, 1000000), "ns": Fraction(1, 1000000000)}
_CHRONO = re.compile(r"^std::(?:__\w+::)?chrono::duration<[^,<>]+(?:,\s*std::(?:__\w+::)?ratio<(\d+)[lLuU]*"
                     r"(?:,\s*(\d+)[lLuU]*)?>)?\s*>$")
_CONDITIONAL = (K.IF_STMT, K.FOR_STMT, K.WHILE_STMT, K.DO_STMT, K.SWITCH_STMT, K.CXX_FOR_RANGE_STMT,
                K.CONDITIONAL_OPERATOR, K.CASE_STMT, K.DEFAULT_STMT)
_PARAMETER_HELPER = re.compile(r"^(?:declare|get)_\w*param", re.I)
_INFINITE = Fraction(9223372036)
_RMW_UNSPECIFIED = {"RMW_DURATION_UNSPECIFIED", "RMW_QOS_DEADLINE_DEFAULT", "RMW_QOS_LIFESPAN_DEFAULT",
                    "RMW_QOS_LIVELINESS_LEASE_DURATION_DEFAULT", "RMW_QOS_DEADLINE_BEST_AVAILABLE",
                    "RMW_QOS_LIVELINESS_LEASE_DURATION_BEST_AVAILABLE"}
_RMW_FIELDS = ("history", "depth", "reliability", "durability", "deadline", "lifespan", "liveliness",
               "liveliness_lease_duration")


@dataclass
class _Mutation:
    """A statement changing a QoS object or rmw profile: `qos.best_effort();`, `p.depth = 5;`."""

    offset: int
    expr: ci.Cursor
    conditional: bool


def node_class(decl: ci.Cursor | None, depth: int = 0) -> bool:
    """rclcpp::Node, rclcpp_lifecycle::LifecycleNode, or a class derived from one of them."""
    if decl is None or depth > 8:
        return False
    if decl.kind in (K.CLASS_DECL, K.STRUCT_DECL, K.CLASS_TEMPLATE):
        if qualified(decl) in NODE_CLASSES:
            return True
        definition = decl.get_definition() or decl
        return any(node_class(base.referenced, depth + 1) for base in definition.get_children()
                   if base.kind == K.CXX_BASE_SPECIFIER)
    return False


def node_method(ref: ci.Cursor, owner: str) -> bool:
    """A method of rclcpp's node classes, or one of a class derived from them that wraps it
    (nav2::LifecycleNode::create_publisher)."""
    return owner in NODE_CLASSES or (ref.kind in (K.CXX_METHOD, K.FUNCTION_TEMPLATE) and
                                     node_class(ref.semantic_parent))


def tokens(expr: ci.Cursor) -> str:
    """An expression as written (comments left out), at most 120 characters."""
    return " ".join(t.spelling for t in expr.get_tokens() if t.kind != ci.TokenKind.COMMENT)[:120]


def macro_name(expr: ci.Cursor) -> str:
    """The macro an expression was expanded from (the word at its expansion point)."""
    location = expr.extent.start
    if location.file is None:
        return ""
    try:
        with open(sandbox.current().check(location.file.name, "source"), "rb") as source:
            source.seek(location.offset)
            match = re.match(rb"\w+", source.read(80))
    except (sandbox.Refused, OSError):
        return ""
    return match.group(0).decode(errors="replace") if match else ""


def parameter_names(function: ci.Cursor) -> list[str]:
    """Parameter names of a function or function template (get_arguments() misses templates)."""
    return [c.spelling for c in function.get_children() if c.kind == K.PARM_DECL]


def derives_from_qos(cls: ci.Cursor | None, depth: int = 0) -> bool:
    """A class derived (directly or not) from rclcpp::QoS, other than rclcpp's own presets."""
    if cls is None or depth > 6 or qualified(cls).startswith("rclcpp::"):
        return False
    definition = cls.get_definition() or cls
    return any(qualified(base.referenced) == "rclcpp::QoS" or derives_from_qos(base.referenced, depth + 1)
               for base in definition.get_children() if base.kind == K.CXX_BASE_SPECIFIER and base.referenced)


def parameter_helper(ref: ci.Cursor) -> tuple[int, int | None] | None:
    """A function wrapping rclcpp's parameter API (nav2's declare_parameter_if_not_declared,
    declare_or_get_parameter...): the positions of its name and default value, by their names."""
    if not _PARAMETER_HELPER.match(ref.spelling) or qualified(ref.semantic_parent) in NODE_CLASSES:
        return None
    params = parameter_names(ref)
    at = next((params.index(p) for p in ("parameter_name", "param_name", "name") if p in params), None)
    if at is None:
        return None
    return at, next((params.index(p) for p in ("default_value", "value", "default") if p in params), None)


def default_argument(function: ci.Cursor, index: int) -> ci.Cursor | None:
    """The default value of a function's parameter, as declared (None when it has none)."""
    params = [c for c in function.get_children() if c.kind == K.PARM_DECL]
    if index >= len(params):
        return None
    value = [c for c in params[index].get_children() if c.kind not in SKIP]
    return value[-1] if value else None


class RclcppWalker:
    """Mixed into the C++ walker: everything ROS 2. Uses the walker's value(), unknown(), add(),
    key(), shown(), from_call_sites() and result."""

    result: object
    file: str
    call_sites: dict[tuple, list[ci.Cursor]]
    param_vars: dict[tuple, Value]
    bindings: dict[tuple, ci.Cursor]

    # -- preparation: what later calls need to know about the whole file --------------------------
    def prepare_ros2(self, cursors: list[ci.Cursor]) -> None:
        """Parameter declarations (their defaults), sub-nodes, QoS mutations, and make_shared calls
        as call sites of the constructors they call."""
        definitions = [c for c in cursors if c.kind in (K.CONSTRUCTOR, K.CXX_METHOD, K.FUNCTION_DECL,
                                                         K.FUNCTION_TEMPLATE) and c.is_definition()]
        self.constructors = [c for c in definitions if c.kind == K.CONSTRUCTOR]
        self.function_spans = [(c.extent.start.offset, c.extent.end.offset) for c in definitions]
        self.declared: dict[str, ci.Cursor] = {}
        self.sub_nodes: dict[tuple, ci.Cursor] = {}
        self.mutations: dict[tuple, list[_Mutation]] = {}
        self.node_names: list[Value] = []
        for cursor in cursors:
            if cursor.kind == K.CALL_EXPR and cursor.referenced is not None:
                self.prepare_call(cursor)
            elif cursor.kind in (K.CONSTRUCTOR, K.CXX_METHOD, K.FUNCTION_DECL, K.LAMBDA_EXPR) and \
                    (cursor.kind == K.LAMBDA_EXPR or cursor.is_definition()):
                body = next((c for c in cursor.get_children() if c.kind == K.COMPOUND_STMT), None)
                if body is not None:
                    self.statements(body, False)
            elif cursor.kind in (K.VAR_DECL, K.FIELD_DECL):
                init = [c for c in cursor.get_children() if c.kind not in SKIP]
                if init and (sub := self.sub_node_call(init[-1])) is not None:
                    self.sub_nodes[self.key(cursor)] = sub

    def prepare_call(self, call: ci.Cursor) -> None:
        ref, args = call.referenced, written_args(call)
        owner = qualified(ref.semantic_parent)
        helper = parameter_helper(ref)
        if call.spelling == "declare_parameter" and owner in NODE_CLASSES and len(args) > 1 and \
                isinstance(name := self.value(args[0]), str):
            self.declared.setdefault(name, args[1])
        elif helper is not None and helper[1] is not None and len(args) > max(helper[0], helper[1]) and \
                isinstance(name := self.value(args[helper[0]]), str):
            self.declared.setdefault(name, args[helper[1]])
        elif call.spelling == "operator=" and len(args) == 2 and (sub := self.sub_node_call(args[1])) is not None:
            target = strip(args[0])
            if target.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR):
                self.sub_nodes[self.key(target.referenced)] = sub
        elif call.spelling in FACTORIES and (cls := self.factory_class(call)) is not None:
            for ctor in cls.get_children():
                if ctor.kind == K.CONSTRUCTOR:
                    self.call_sites.setdefault(self.key(ctor.canonical), []).append(call)
        elif ref.spelling in ("get_parameter", "get_parameter_or") and owner in NODE_CLASSES and \
                len(args) == (2 if ref.spelling == "get_parameter" else 3) and \
                isinstance(name := self.value(args[0]), str):
            # get_parameter("name", variable), get_parameter_or("name", variable, alternative)
            target = next((c for c in args[1].walk_preorder() if c.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR)),
                          None)
            if target is not None:
                self.param_vars[self.key(target.referenced)] = self.parameter_value(
                    name, args[2] if len(args) == 3 else None, call)

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
            root = strip(next(expr.get_children())) if expr.spelling == "operator=" else self.chain_root(expr)
        elif expr.kind == K.BINARY_OPERATOR and binary_operator(expr) == "=":
            lhs = strip(next(expr.get_children()))
            root = lhs if lhs.kind == K.DECL_REF_EXPR else \
                next((c for c in lhs.get_children() if c.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR)), lhs)
        if root is not None and root.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and root.referenced is not None:
            self.mutations.setdefault(self.key(root.referenced), []).append(
                _Mutation(expr.extent.start.offset, expr, conditional))

    @staticmethod
    def chain_root(call: ci.Cursor) -> ci.Cursor | None:
        """The object a chain of method calls starts from: `qos` in `qos.keep_last(5).reliable()`."""
        expr = call
        for _ in range(16):
            expr = strip(expr)
            if expr.kind == K.CALL_EXPR:
                callee = next(expr.get_children(), None)
                if callee is None or callee.kind != K.MEMBER_REF_EXPR:
                    return None
                inner = next(callee.get_children(), None)
                if inner is None:
                    return None
                expr = inner
            else:
                return expr
        return None

    def sub_node_call(self, expr: ci.Cursor) -> ci.Cursor | None:
        found = next((c for c in expr.walk_preorder() if c.kind == K.CALL_EXPR and c.spelling == "create_sub_node"),
                     None)
        return found if found is not None and written_args(found) else None

    @staticmethod
    def factory_class(call: ci.Cursor) -> ci.Cursor | None:
        """The class std::make_shared<T> / T::make_shared / make_unique constructs."""
        ref = call.referenced
        if ref.semantic_parent is not None and ref.semantic_parent.kind in (K.CLASS_DECL, K.STRUCT_DECL,
                                                                              K.CLASS_TEMPLATE):
            return ref.semantic_parent
        type_ = call.type.get_canonical()
        if type_.get_num_template_arguments() > 0:
            declaration = type_.get_template_argument_type(0).get_canonical().get_declaration()
            return declaration if declaration.kind != K.NO_DECL_FOUND else None
        return None

    # -- API calls --------------------------------------------------------------------------------
    def rclcpp_call(self, call: ci.Cursor, ref: ci.Cursor, owner: str, name: str, args: list[ci.Cursor]) -> bool:
        """Read one call if it is ROS 2 API; True when it was."""
        if ref.kind == K.CONSTRUCTOR and node_class(ref.semantic_parent):
            self.node_constructed(call, args, ref)
        elif name in FACTORIES:
            cls = self.factory_class(call)
            if cls is not None and qualified(cls) in NODE_CLASSES:
                self.node_constructed(call, args, None)
            elif cls is not None and qualified(cls) in CONSTRUCTED_ROS2:
                self.constructed_ros2(call, qualified(cls), args, cls)
            else:
                return False
        elif ref.kind == K.CONSTRUCTOR and owner in CONSTRUCTED_ROS2:
            self.constructed_ros2(call, owner, args, ref.semantic_parent)
        elif name in ENTITIES and node_method(ref, owner):
            self.entity(call, ref, ENTITIES[name], args, self.node_ns(self.object_of(call)), name)
        elif (owner, name) in FREE_FUNCTIONS and args:
            self.entity(call, ref, FREE_FUNCTIONS[(owner, name)], args, self.node_ns(args[0]), name)
        elif owner == "image_transport::ImageTransport" and name in IMAGE_TRANSPORT_METHODS and args:
            self.entity(call, ref, IMAGE_TRANSPORT_METHODS[name], args, "", name)
        elif owner == "message_filters::Subscriber" and name == "subscribe" and len(args) > 1:
            self.constructed_ros2(call, owner, args, ref.semantic_parent)
        elif owner in NODE_CLASSES and name in PARAMETER_READS and args:
            self.parameter_read(call, name, args)
        elif (helper := parameter_helper(ref)) is not None and helper[0] < len(args):
            at, default = helper
            given = args[default] if default is not None and default < len(args) else None
            pname = self.value(args[at])
            fallback = given if given is not None else self.declared.get(pname) if isinstance(pname, str) else None
            self.add("param_read", call, pname, "", "~", self.value(fallback) if fallback is not None else None)
        elif owner in NODE_CLASSES and name in PARAMETER_WRITES and args:
            self.parameter_write(call, args)
        elif name in ("create_wall_timer", "create_timer") and (node_method(ref, owner) or owner == "rclcpp") and \
                "period" in (params := parameter_names(ref)) and params.index("period") < len(args):
            self.add("timer", call, self.period(args[params.index("period")]), "", "")
        elif ref.kind == K.CONSTRUCTOR and owner in ("rclcpp::Rate", "rclcpp::WallRate", "rclcpp::GenericRate") \
                and args:
            hz = number(self.value(args[0])) if isinstance(self.value(args[0]), str) else None
            period = seconds_text(1 / hz) if hz else self.period(args[0])
            self.add("timer", call, period or self.unknown(call, "rate not constant"), "", "")
        else:
            return False
        return True

    def object_of(self, call: ci.Cursor) -> ci.Cursor | None:
        """`node` in `node->create_publisher(...)`; None for an implicit `this`."""
        callee = next(call.get_children(), None)
        if callee is not None and callee.kind == K.MEMBER_REF_EXPR:
            return next(callee.get_children(), None)
        return None

    def node_ns(self, expr: ci.Cursor | None, depth: int = 0) -> Value:
        """The namespace an entity created on this node gets: "" for the node itself, the
        sub-namespace for a node made by create_sub_node()."""
        if expr is None or depth > 4:
            return ""
        for cursor in expr.walk_preorder():
            if cursor.kind == K.CALL_EXPR and cursor.spelling == "create_sub_node" and written_args(cursor):
                parent = self.node_ns(self.object_of(cursor), depth + 1)
                sub = self.value(written_args(cursor)[0])
                return concat(parent, "/", sub) if parent else sub
            if cursor.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and cursor.referenced is not None:
                sub_call = self.sub_nodes.get(self.key(cursor.referenced))
                return self.node_ns(sub_call, depth + 1) if sub_call is not None else ""
        return ""

    def node_constructed(self, call: ci.Cursor, args: list[ci.Cursor], ctor: ci.Cursor | None) -> None:
        """A node's name and namespace from its constructor: rclcpp::Node("name", "ns", options),
        a subclass's base initializer, std::make_shared<rclcpp::Node>(...), Node::make_shared(...)."""
        names = parameter_names(ctor) if ctor is not None else ["node_name", "namespace_"]
        if ctor is not None and qualified(ctor.semantic_parent) not in NODE_CLASSES and not self.base_init(call):
            return  # a subclass constructed in this file: its own base initializer names it
        texts = [(n, a) for n, a in zip(names, args) if "string" in a.type.get_canonical().spelling
                 or "char" in a.type.spelling]
        name = next((a for n, a in texts if n in ("node_name", "name")), texts[0][1] if texts else None)
        if name is None:
            return
        value = self.value(name)
        namespace = next((a for n, a in texts if n in ("namespace_", "namespace", "ns", "node_namespace")), None)
        if self.node_names and value not in self.node_names:
            self.result.diagnostics.append(Diagnostic(
                self.shown(call), call.location.line, "cpp-several-nodes", f"this file creates several nodes "
                f"({self.node_names[0]}, {value}); archlog reads them as one node named after the first", "note"))
        self.node_names.append(value)
        if self.result.default_name is None:
            self.result.default_name = value
            self.result.namespace = self.value(namespace) if namespace is not None else ""
            self.result.name_file, self.result.name_line = self.shown(call), call.location.line

    def base_init(self, call: ci.Cursor) -> bool:
        """A call in a constructor's initializer list (a base class initializer)."""
        return any(call.extent.start.offset >= c.extent.start.offset and call.extent.end.offset <= c.extent.end.offset
                   and call.extent.start.offset < body.extent.start.offset
                   for c in self.constructors for body in c.get_children() if body.kind == K.COMPOUND_STMT)

    def entity(self, call: ci.Cursor, ref: ci.Cursor, kind: str, args: list[ci.Cursor], handle: Value,
               method: str) -> None:
        """A publisher, subscription, service, client or action server/client."""
        params = parameter_names(ref)
        position = next((params.index(p) for p in NAME_PARAMETERS if p in params), 0)
        if position >= len(args):
            return
        topic = self.value(args[position])
        if method.startswith("create_generic"):
            type_: Value = self.value(args[position + 1]) if len(args) > position + 1 else \
                self.unknown(call, "type not given")
        elif "image_transport" in qualified(ref.semantic_parent) or method in IMAGE_TRANSPORT_METHODS:
            type_ = "sensor_msgs/msg/Image"
        else:
            type_ = self.entity_type(call) or self.unknown(call, "message type not resolved")
        qos: tuple[tuple[str, str], ...] = ()
        if kind in ("publisher", "subscriber"):
            at = next((params.index(p) for p in QOS_PARAMETERS if p in params), -1)
            given = args[at] if 0 <= at < len(args) else default_argument(ref, at) if at >= 0 else None
            default = "default" if "image_transport" in qualified(ref.semantic_parent) else None
            qos = self.qos(given, call, default)
        self.add(kind, call, topic, type_, handle, qos=qos)
        if method.endswith(("Camera", "camera_publisher", "camera_subscription")):
            self.add(kind, call, camera_info(topic), "sensor_msgs/msg/CameraInfo", handle, qos=qos)

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
                self.unknown(call, "message type not resolved")
            self.add("subscriber", call, self.value(args[1]), type_, self.node_ns(args[0]),
                     qos=self.qos(args[2] if len(args) > 2 else None, call, "default"))
            return
        params = parameter_names(call.referenced) if call.referenced.kind == K.CONSTRUCTOR else []
        given = next((args[params.index("qos")] for _ in [0] if "qos" in params and params.index("qos") < len(args)),
                     None)
        for kind, topic, type_, qos in TF2[owner]:
            facts = self.qos(given, call) if given is not None and owner != "tf2_ros::TransformListener" else \
                self.builtin_qos(qos)
            self.add(kind, call, topic, type_, "", qos=facts)

    @staticmethod
    def builtin_qos(partial: Qos) -> tuple[tuple[str, str], ...]:
        """A library's own QoS: rclcpp::QoS(depth) with the given changes."""
        qos = Qos.preset("default")
        qos.policies.update(partial.policies)
        return qos.facts()

    # -- parameters -------------------------------------------------------------------------------
    def parameter_read(self, call: ci.Cursor, method: str, args: list[ci.Cursor]) -> None:
        name = self.value(args[0])
        if method == "declare_parameter" and len(args) > 1 and "ParameterType" not in args[1].type.spelling:
            default: Value | None = self.value(args[1])
        elif method == "get_parameter_or" and len(args) > 1:
            default = self.value(args[-1])
        elif isinstance(name, str) and name in self.declared:
            default = self.value(self.declared[name])
        else:
            default = None
        self.add("param_read", call, name, "", "~", default)

    def parameter_write(self, call: ci.Cursor, args: list[ci.Cursor]) -> None:
        """set_parameter(rclcpp::Parameter("name", value)) and set_parameters({...})."""
        for cursor in args[0].walk_preorder():
            if cursor.kind == K.CALL_EXPR and cursor.referenced is not None and \
                    cursor.referenced.kind == K.CONSTRUCTOR and qualified(cursor.referenced.semantic_parent) == \
                    "rclcpp::Parameter" and len(pair := written_args(cursor)) == 2:
                self.add("param_write", call, self.value(pair[0]), "", "~", self.value(pair[1]))

    def parameter_value(self, name: str, default: ci.Cursor | None, call: ci.Cursor) -> ParamRef:
        """A value read from a node parameter, with its default (the declaration's, if any)."""
        default = default if default is not None else self.declared.get(name)
        fallback = self.value(default) if default is not None else self.unknown(call, "parameter without default")
        return ParamRef(name, fallback, "~", self.shown(call), call.location.line)

    def rclcpp_value(self, expr: ci.Cursor, owner: str, name: str, args: list[ci.Cursor], depth: int) -> Value | None:
        """Values of rclcpp calls: parameters read, ParameterValue(x), get_name(), get_namespace()."""
        if owner in NODE_CLASSES and name in PARAMETER_READS and args and \
                isinstance(pname := self.value(args[0], depth + 1), str):
            if name == "declare_parameter":
                default = args[1] if len(args) > 1 and "ParameterType" not in args[1].type.spelling else None
            else:
                default = args[-1] if name == "get_parameter_or" and len(args) > 1 else None
            return self.parameter_value(pname, default, expr)
        if (helper := parameter_helper(expr.referenced)) is not None and helper[0] < len(args) and \
                isinstance(pname := self.value(args[helper[0]], depth + 1), str):
            given = args[helper[1]] if helper[1] is not None and helper[1] < len(args) else None
            return self.parameter_value(pname, given, expr)
        if owner in ("rclcpp::Parameter", "rclcpp::ParameterValue") and (name.startswith("as_") or name in (
                "get_value", "get", "get_parameter_value")):
            obj = self.object_of(expr)
            return self.value(obj, depth + 1) if obj is not None else None
        if owner == "rclcpp::ParameterValue" and expr.referenced.kind == K.CONSTRUCTOR and len(args) == 1:
            return self.value(args[0], depth + 1)
        if owner in NODE_CLASSES and name in ("get_name", "get_fully_qualified_name"):
            return "~"
        return None

    # -- durations --------------------------------------------------------------------------------
    def period(self, expr: ci.Cursor) -> Value:
        """A timer period in decimal seconds."""
        seconds = self.seconds(expr)
        return seconds_text(seconds) or self.unknown(expr, "zero period") if seconds is not None else \
            self.unknown(expr, "timer period not resolved")

    def seconds(self, expr: ci.Cursor, depth: int = 0) -> Fraction | None:
        """A duration in seconds: chrono literals (500ms), std::chrono durations, rclcpp::Duration,
        rmw_time_t {sec, nsec}; None when it is not known statically."""
        expr = strip(expr)
        if depth > 8:
            return None
        literal = _CHRONO_LITERAL.match(tokens(expr).replace(" ", ""))
        if literal:
            return Fraction(literal.group(1)) * _CHRONO_UNITS[literal.group(2)]
        if expr.kind == K.INIT_LIST_EXPR and not tokens(expr):  # from a macro: rmw's duration macros
            macro = macro_name(expr)
            return _INFINITE if macro == "RMW_DURATION_INFINITE" else Fraction(0) if macro in _RMW_UNSPECIFIED else None
        if expr.kind == K.INIT_LIST_EXPR:
            parts = [number(v) if isinstance(v := self.value(c, depth + 1), str) else None
                     for c in expr.get_children()]
            return parts[0] + parts[1] / 1_000_000_000 if len(parts) == 2 and None not in parts else None
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
                whole, nanos = (number(v) if isinstance(v := self.value(a, depth + 1), str) else None for a in args)
                return whole + nanos / 1_000_000_000 if whole is not None and nanos is not None else None
            return self.seconds(args[0], depth + 1) if args else None
        if owner == "rclcpp::Duration" and ref.spelling in ("from_seconds", "from_nanoseconds") and args:
            value = self.value(args[0], depth + 1)
            amount = number(value) if isinstance(value, str) else None
            return None if amount is None else amount if ref.spelling == "from_seconds" else amount / 1_000_000_000
        if ref.spelling == "duration_cast" and args:
            return self.seconds(args[0], depth + 1)
        if ref.kind == K.CONSTRUCTOR and scale is not None and len(args) == 1:
            inner = strip(args[0])
            if _CHRONO.match(inner.type.get_canonical().spelling):
                return self.seconds(inner, depth + 1)
            value = self.value(args[0], depth + 1)
            amount = number(value) if isinstance(value, str) else None
            return amount * scale if amount is not None else None
        if ref.kind == K.CONSTRUCTOR and len(args) == 1:  # copy or conversion
            return self.seconds(args[0], depth + 1)
        return None

    # -- QoS --------------------------------------------------------------------------------------
    def qos(self, expr: ci.Cursor | None, at: ci.Cursor, default: str | None = None) -> tuple[tuple[str, str], ...]:
        """The QoS facts of an entity's QoS argument (`default`: the preset when there is none)."""
        if expr is None:
            return Qos.preset(default).facts() if default else Qos.unknown(tokens(at)).facts()
        return self.qos_value(expr, 0).facts()

    def qos_value(self, expr: ci.Cursor, depth: int) -> Qos:
        """Read a QoS expression: a depth, rclcpp::QoS(...) and its presets, builder chains, rmw
        profiles, and variables holding any of these (with the statements changing them)."""
        text = tokens(expr)
        expr = strip(expr)
        if depth > 10:
            return Qos.unknown(text)
        type_name = expr.type.get_canonical().spelling
        if expr.kind == K.INTEGER_LITERAL or expr.type.get_canonical().kind in _INTEGERS:
            return self.depth_qos(expr, text)
        if expr.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and expr.referenced is not None:
            return self.qos_variable(expr, depth, text)
        if expr.kind == K.INIT_LIST_EXPR and "rmw_qos_profile" in type_name:
            return self.rmw_aggregate(expr, text)
        if expr.kind != K.CALL_EXPR or expr.referenced is None:
            return Qos.unknown(text)
        ref, args = expr.referenced, written_args(expr)
        owner = qualified(ref.semantic_parent)
        cls = owner.rsplit("::", 1)[-1]
        if ref.kind == K.CONSTRUCTOR and owner.startswith("rclcpp::") and PRESET_NAMES.get(cls) and cls != "QoS":
            qos = Qos.preset(PRESET_NAMES[cls])
            if args:
                qos.initialise(*self.qos_initialization(args[0], depth), text)
            return qos
        if ref.kind == K.CONSTRUCTOR and owner == "rclcpp::QoS":
            return self.qos_constructed(args, depth, text)
        if ref.kind == K.CONSTRUCTOR and derives_from_qos(ref.semantic_parent):
            return self.qos_subclass(ref, args, depth, text)
        if owner == "rclcpp::QoS" and ref.spelling in ("get_rmw_qos_profile",):
            obj = self.object_of(expr)
            return self.qos_value(obj, depth + 1) if obj is not None else Qos.unknown(text)
        if owner == "rclcpp::QoS" and ref.kind == K.CXX_METHOD:
            obj = self.object_of(expr)
            base = self.qos_value(obj, depth + 1).copy() if obj is not None else Qos.unknown(text)
            self.qos_apply(base, ref.spelling, args[0] if args else None, text)
            return base
        if ref.kind == K.CONSTRUCTOR and len(args) == 1:  # a copy
            return self.qos_value(args[0], depth + 1)
        if ref.kind in (K.FUNCTION_DECL, K.CXX_METHOD) and (body := self.single_return(ref)) is not None:
            return self.qos_value(body, depth + 1)
        return Qos.unknown(text)

    def qos_subclass(self, ctor: ci.Cursor, args: list[ci.Cursor], depth: int, text: str) -> Qos:
        """A class derived from rclcpp::QoS (nav2::qos::LatchedPublisherQoS): its constructor's
        base initializer, with the arguments (or defaults) bound to its parameters, then the
        builder calls its body makes on `this`."""
        definition = ctor.get_definition()
        if definition is None:
            return Qos.unknown(text)
        params = [c for c in definition.get_children() if c.kind == K.PARM_DECL]
        bound = {self.key(p): args[i] if i < len(args) else default_argument(definition, i)
                 for i, p in enumerate(params)}
        if any(value is None for value in bound.values()):
            return Qos.unknown(text)
        children = list(definition.get_children())
        body = next((c for c in children if c.kind == K.COMPOUND_STMT), None)
        base = next((c for c in children if c.kind in (K.CALL_EXPR, K.UNEXPOSED_EXPR)
                     and (body is None or c.extent.start.offset < body.extent.start.offset)), None)
        self.bindings.update(bound)
        try:
            qos = self.qos_value(base, depth + 1).copy() if base is not None else Qos.unknown(text)
            for stmt in body.get_children() if body is not None else []:
                call = strip(stmt)
                root = self.chain_root(call) if call.kind == K.CALL_EXPR and call.referenced is not None and \
                    qualified(call.referenced.semantic_parent) == "rclcpp::QoS" else None
                if root is not None and root.kind == K.CXX_THIS_EXPR:
                    qos = self.replay(qos, call, depth + 1)
                else:
                    qos.unread.append(text)
        finally:
            for key in bound:
                self.bindings.pop(key, None)
        return qos

    def depth_qos(self, expr: ci.Cursor, text: str) -> Qos:
        qos = Qos.preset("default")
        value = self.value(expr)
        qos.initialise("keep_last", value if isinstance(value, str) and number(value) is not None else None, text)
        return qos

    def qos_constructed(self, args: list[ci.Cursor], depth: int, text: str) -> Qos:
        """rclcpp::QoS(depth), QoS(KeepLast(n)), QoS(initialization, rmw_profile), a copy."""
        if not args:
            return Qos.unknown(text)
        first = strip(args[0])
        first_type = first.type.get_canonical().spelling
        if first.type.get_canonical().kind in _INTEGERS or first.kind == K.INTEGER_LITERAL:
            return self.depth_qos(first, text)
        if "QoSInitialization" in first_type or "KeepLast" in first_type or "KeepAll" in first_type:
            qos = self.qos_value(args[1], depth + 1).copy() if len(args) > 1 else Qos.preset("default")
            if len(args) == 1:
                qos.profile = ""
            qos.initialise(*self.qos_initialization(args[0], depth), text)
            return qos
        return self.qos_value(args[0], depth + 1)

    def qos_initialization(self, expr: ci.Cursor, depth: int) -> tuple[str | None, str | None]:
        """History and depth of a QoSInitialization: KeepLast(n), KeepAll(), from_rmw(profile)."""
        expr = strip(expr)
        if expr.kind == K.CALL_EXPR and expr.referenced is not None:
            owner, args = qualified(expr.referenced.semantic_parent), written_args(expr)
            if owner == "rclcpp::KeepAll" or expr.spelling == "KeepAll":
                return "keep_all", None
            if (owner == "rclcpp::KeepLast" or expr.spelling == "KeepLast") and args:
                value = self.value(args[0])
                return "keep_last", value if isinstance(value, str) and number(value) is not None else None
            if expr.spelling == "from_rmw" and args:
                profile = self.qos_value(args[0], depth + 1)
                return profile.policies.get("history"), profile.policies.get("depth")
            if expr.referenced.kind == K.CONSTRUCTOR and len(args) == 1:
                return self.qos_initialization(args[0], depth + 1)
        return None, None

    def qos_apply(self, qos: Qos, method: str, arg: ci.Cursor | None, text: str) -> None:
        """One builder method: .reliable(), .keep_last(5), .durability(...), .deadline(100ms)..."""
        if arg is None:
            qos.apply(method, None, text)
        elif method in ("deadline", "lifespan", "liveliness_lease_duration"):
            seconds = self.seconds(arg)
            qos.apply(method, seconds_text(seconds) if seconds is not None else None, text)
        elif method in ("keep_last", "depth"):
            value = self.value(arg)
            qos.apply(method, value if isinstance(value, str) and number(value) is not None else None, text)
        elif method in ("history", "reliability", "durability", "liveliness"):
            qos.apply(method, self.enum_spelling(arg), text)

    def enum_spelling(self, expr: ci.Cursor, depth: int = 0) -> str | None:
        """The enumerator an expression names (`rclcpp::ReliabilityPolicy::BestEffort`,
        `RMW_QOS_POLICY_RELIABILITY_RELIABLE`), through constants."""
        expr = strip(expr)
        if expr.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) and expr.referenced is not None and depth < 4:
            ref = expr.referenced
            if ref.kind == K.ENUM_CONSTANT_DECL:
                return qualified(ref)
            init = [c for c in ref.get_children() if c.kind not in SKIP]
            if ref.kind == K.VAR_DECL and init and ref.type.is_const_qualified():
                return self.enum_spelling(init[-1], depth + 1)
        return None

    def qos_variable(self, expr: ci.Cursor, depth: int, text: str) -> Qos:
        """A variable or member holding a QoS or an rmw profile: its initial value, then the
        statements before this use that change it (in a condition: the policy is unknown)."""
        decl = expr.referenced
        if decl.spelling in PRESET_NAMES and not self.in_main(decl):
            return Qos.preset(PRESET_NAMES[decl.spelling])
        if decl.kind == K.PARM_DECL:
            return self.qos_parameter(decl, expr, depth, text)
        if decl.kind not in (K.VAR_DECL, K.FIELD_DECL):
            return Qos.unknown(text)
        init = [c for c in decl.get_children() if c.kind not in SKIP]
        initial = init[-1] if init else self.member_initializer(decl)
        if initial is None:
            return Qos.unknown(text)
        qos = self.qos_value(initial, depth + 1).copy()
        for change in sorted(self.mutations.get(self.key(decl), []), key=lambda m: m.offset):
            if change.offset < expr.extent.start.offset or not self.same_function(change.expr, expr):
                self.qos_mutation(qos, change, decl, depth)
        return qos

    def qos_mutation(self, qos: Qos, change: _Mutation, decl: ci.Cursor, depth: int) -> None:
        expr, text = change.expr, tokens(change.expr)
        if expr.kind == K.BINARY_OPERATOR:
            lhs, rhs = [strip(c) for c in expr.get_children()][:2]
            field_name = lhs.spelling if lhs.kind == K.MEMBER_REF_EXPR and lhs.referenced != decl else None
            if field_name is None:
                replaced = self.qos_value(rhs, depth + 1)
                qos.policies, qos.profile, qos.unread = replaced.policies, replaced.profile, replaced.unread
            elif field_name in _RMW_FIELDS:
                self.qos_apply(qos, field_name, rhs, text)
        elif expr.kind == K.CALL_EXPR:
            replayed = self.replay(qos, expr, depth)
            qos.policies, qos.profile, qos.unread = replayed.policies, replayed.profile, replayed.unread
        if change.conditional:
            for method in self.changed_policies(expr):
                qos.set(method, None, text)

    def replay(self, qos: Qos, call: ci.Cursor, depth: int) -> Qos:
        """Apply a statement's chain of builder calls (`qos.keep_last(5).reliable();`) to `qos`."""
        chain: list[ci.Cursor] = []
        expr = strip(call)
        while expr.kind == K.CALL_EXPR and expr.referenced is not None and \
                qualified(expr.referenced.semantic_parent) == "rclcpp::QoS":
            chain.append(expr)
            obj = self.object_of(expr)
            if obj is None:
                break
            expr = strip(obj)
        result = qos.copy()
        if expr.kind == K.CALL_EXPR and expr.spelling == "operator=":
            return self.qos_value(written_args(expr)[-1], depth + 1)
        for link in reversed(chain):
            args = written_args(link)
            if link.spelling == "operator=" and args:
                result = self.qos_value(args[-1], depth + 1).copy()
            else:
                self.qos_apply(result, link.spelling, args[0] if args else None, tokens(link))
        return result

    @staticmethod
    def changed_policies(expr: ci.Cursor) -> list[str]:
        """The policies a statement may change (for statements that run only under a condition)."""
        words = {t.spelling for t in expr.get_tokens()}
        found = [FIXED_SETTERS[w][0] for w in words if w in FIXED_SETTERS]
        found += [w for w in words if w in _RMW_FIELDS]
        found += ["depth"] if "keep_last" in words else []
        return found

    def qos_parameter(self, decl: ci.Cursor, expr: ci.Cursor, depth: int, text: str) -> Qos:
        """A function parameter: the QoS all call sites in this file pass."""
        function = decl.semantic_parent
        params = parameter_names(function) if function is not None else []
        index = params.index(decl.spelling) if decl.spelling in params else -1
        sites = self.call_sites.get(self.key(function.canonical), []) if index >= 0 else []
        found = [self.qos_value(args[index], depth + 1) for site in sites if len(args := written_args(site)) > index]
        if found and all(q.facts() == found[0].facts() for q in found):
            return found[0]
        return Qos.unknown(text)

    def member_initializer(self, decl: ci.Cursor) -> ci.Cursor | None:
        """The expression a member is initialised with in a constructor's initializer list."""
        for ctor in self.constructors:
            children = list(ctor.get_children())
            for member, init in zip(children, children[1:]):
                if member.kind == K.MEMBER_REF and member.referenced == decl:
                    return init
        return None

    def rmw_aggregate(self, expr: ci.Cursor, text: str) -> Qos:
        """rmw_qos_profile_t p = {history, depth, reliability, durability, deadline, ...}."""
        qos = Qos({}, "")
        for field_name, value in zip(_RMW_FIELDS, expr.get_children()):
            self.qos_apply(qos, field_name, value, text)
        return qos

    def single_return(self, function: ci.Cursor) -> ci.Cursor | None:
        """The expression of a function in this file whose body is one return statement."""
        definition = function.get_definition()
        if definition is None or not self.in_main(definition):
            return None
        body = next((c for c in definition.get_children() if c.kind == K.COMPOUND_STMT), None)
        statements = list(body.get_children()) if body is not None else []
        if len(statements) == 1 and statements[0].kind == K.RETURN_STMT:
            return next(statements[0].get_children(), None)
        return None

    def same_function(self, a: ci.Cursor, b: ci.Cursor) -> bool:
        """Whether two cursors are in the same function definition of this file."""
        def owner(cursor: ci.Cursor) -> int:
            return next((i for i, (start, end) in enumerate(self.function_spans)
                         if start <= cursor.extent.start.offset <= end), -1)
        return owner(a) == owner(b)

    # -- when the AST is incomplete ---------------------------------------------------------------
    def ros2_fallback(self, text: str, covered: set[int], tu: ci.TranslationUnit) -> None:
        """Read rclcpp entity calls, action servers/clients and the node's name from the text of
        lines where the AST produced nothing (type aliases from the file and the workspace headers
        it includes)."""
        aliases = type_aliases([text, *_workspace_header_texts(tu)])
        sub_nodes = {m.group(1): unquote(m.group(2)) for m in re.finditer(
            r"(\w+)\s*=\s*(?:this\s*->\s*)?create_sub_node\s*\(\s*(\"[^\"]*\")", text)}
        line_of = line_finder(text)
        for match in [*_ENTITY_FALLBACK.finditer(text), *_ACTION_FALLBACK.finditer(text)]:
            line = line_of(match.start())
            if line in covered or (self.spans is not None and not any(a <= line <= b for a, b in self.spans)):
                continue
            method, template, first = match.group("method", "type", "name")
            obj = match.group("obj") if "obj" in match.re.groupindex else None
            kind = ENTITIES[method] if match.re is _ENTITY_FALLBACK else \
                ("action_server" if method == "create_server" else "action_client")
            name: Value = unquote(first) if first.startswith('"') else \
                Unknown(f"{first} (read from tokens)", self.file, line)
            type_: Value = type_from_spelling(aliases.get(template, template)) or \
                Unknown(f"{method}<{template}> (type not readable without the AST)", self.file, line)
            qos: tuple[tuple[str, str], ...] = ()
            if kind in ("publisher", "subscriber"):
                qos = text_qos(_next_argument(text, match.end()))
            self.result.ports.append(Port(kind, name, type_, self.file, line, 0, sub_nodes.get(obj or "", ""),
                                          qos=qos))
            self.result.fallback_lines.append(line)
        for named in _NODE_FALLBACK.finditer(text) if self.result.default_name is None else []:
            line = line_of(named.start())
            if self.spans is None or any(a <= line <= b for a, b in self.spans):
                self.result.default_name = unquote(named.group(1))
                self.result.name_file, self.result.name_line = self.file, line
                break


_ENTITY_FALLBACK = re.compile(
    r"(?:\b(?P<obj>\w+)\s*(?:\.|->)\s*)?(?<!::)\b(?P<method>create_publisher|create_subscription|create_service|"
    r"create_client)\s*<\s*(?P<type>[\w:]+)[^>;]*>\s*\(\s*(?P<name>\"(?:[^\"\\]|\\.)*\"|[\w:.>\-]+)")
_ACTION_FALLBACK = re.compile(
    r"\brclcpp_action::(?P<method>create_server|create_client)\s*<\s*(?P<type>[\w:]+)[^>;]*>\s*\(\s*[^,;]+?,\s*"
    r"(?P<name>\"(?:[^\"\\]|\\.)*\"|[\w:.>\-]+)")
_ALIAS = re.compile(r"\busing\s+(\w+)\s*=\s*(?:typename\s+)?([\w:]+)\s*;|\btypedef\s+([\w:]+)\s+(\w+)\s*;"
                    r"|\busing\s+((?:\w+::)+(\w+))\s*;")


def type_aliases(texts: list[str]) -> dict[str, str]:
    """`using X = a::b::C;`, `typedef a::b::C X;` and `using a::b::C;` in C++ texts: name -> type."""
    found: dict[str, str] = {}
    for text in texts:
        for m in _ALIAS.finditer(text):
            found.setdefault(m.group(1) or m.group(4) or m.group(6), m.group(2) or m.group(3) or m.group(5))
    return found


def _workspace_header_texts(tu: ci.TranslationUnit) -> list[str]:
    """The texts of the headers a unit includes that are not installed ones nor stand-ins."""
    texts = []
    for include in tu.get_includes():
        name = include.include.name
        if not name.startswith(("/usr/", "/opt/", str(cache_dir()), str(API_DIR))):
            try:
                texts.append(sandbox.read_text(name, "source"))
            except sandbox.Refused:
                continue
    return texts
_NODE_FALLBACK = re.compile(r"[:,]\s*(?:rclcpp::Node|Node|(?:rclcpp_lifecycle::)?LifecycleNode)\s*\(\s*(\"[^\"]+\")")


def _next_argument(text: str, start: int) -> str:
    """The argument after the one ending at `start` (for the QoS after a topic name), within
    CALL_WINDOW characters."""
    text = text[start: start + CALL_WINDOW]
    depth, index = 0, 0
    while index < len(text) and not (depth == 0 and text[index] in ",)"):
        depth += text[index] in "([{<"
        depth -= text[index] in ")]}>"
        index += 1
    begin = index + 1
    depth, index = 0, begin
    while index < len(text) and not (depth == 0 and text[index] in ",);"):
        depth += text[index] in "([{"
        depth -= text[index] in ")]}"
        index += 1
    return text[begin:index]


_INTEGERS = (ci.TypeKind.INT, ci.TypeKind.UINT, ci.TypeKind.LONG, ci.TypeKind.ULONG, ci.TypeKind.LONGLONG,
             ci.TypeKind.ULONGLONG, ci.TypeKind.SHORT, ci.TypeKind.USHORT, ci.TypeKind.UCHAR, ci.TypeKind.SCHAR)


def text_qos(text: str) -> tuple[tuple[str, str], ...]:
    """QoS from the text of an argument, for calls the AST lost: a depth, rclcpp::QoS(n),
    QoS(KeepLast(n)), QoS(KeepAll()), a preset class or rmw profile, then builder calls."""
    text = text.strip()
    head = re.match(r"^(?:rclcpp::)?(\w+)\s*(?:\((.*?)\)|\{(.*?)\})?\s*(?=\.|$)", text)
    if re.fullmatch(r"\d+", text):
        qos = Qos.preset("default")
        qos.initialise("keep_last", text, text)
        return qos.facts()
    if head is None or head.group(1) not in PRESET_NAMES:
        return Qos.unknown(text).facts()
    qos = Qos.preset(PRESET_NAMES[head.group(1)])
    inner = (head.group(2) or head.group(3) or "").strip()
    last = re.fullmatch(r"(?:rclcpp::)?KeepLast\s*[({]\s*(\d+)\s*[)}]\)?|(\d+)", inner)
    if head.group(1) == "QoS":
        if last is None and "KeepAll" not in inner:
            return Qos.unknown(text).facts()
        qos.initialise(*(("keep_all", None) if "KeepAll" in inner else ("keep_last", last.group(1) or last.group(2))),
                       text)
    for method, argument in re.findall(r"\.\s*(\w+)\s*\(([^()]*(?:\([^()]*\))?[^()]*)\)", text[head.end():]):
        argument = argument.strip()
        if method in ("deadline", "lifespan", "liveliness_lease_duration"):
            literal = _CHRONO_LITERAL.match(argument.replace(" ", ""))
            qos.apply(method, seconds_text(Fraction(literal.group(1)) * _CHRONO_UNITS[literal.group(2)])
                      if literal else None, text)
        elif not qos.apply(method, argument or None, text):
            qos.unread.append(text)
    return qos.facts()

