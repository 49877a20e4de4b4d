"""The rclcpp API as the rclcpp readers recognise it: the names of its calls and classes, and
helpers over the cursors of its calls (node classes, parameter helpers, call chains)."""

from __future__ import annotations

import re

import clang.cindex as ci

from archlog import sandbox
from archlog.extract.cpp.clang_ast import SKIP, K, qualified, strip, written_args

LIFECYCLE_NODE = "rclcpp_lifecycle::LifecycleNode"
NODE_CLASSES = ("rclcpp::Node", LIFECYCLE_NODE)
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
FACTORIES = {"make_shared", "make_unique", "allocate_shared"}
_PARAMETER_HELPER = re.compile(r"^(?:declare|get)_\w*param", re.I)


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


def object_of(call: ci.Cursor) -> ci.Cursor | None:
    """`node` in `node->create_publisher(...)`; None for an implicit `this`."""
    callee = next(call.get_children(), None)
    if callee is not None and callee.kind == K.MEMBER_REF_EXPR:
        return next(callee.get_children(), None)
    return None


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


def sub_node_call(expr: ci.Cursor) -> ci.Cursor | None:
    found = next((c for c in expr.walk_preorder() if c.kind == K.CALL_EXPR and c.spelling == "create_sub_node"),
                 None)
    return found if found is not None and written_args(found) else None


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
