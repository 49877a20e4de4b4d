"""libclang helpers shared by the roscpp walker (roscpp.py), the rclcpp one (rclcpp/) and behavior:
qualified names, written arguments, literals, ROS message types from C++ types, assignments,
expressions below implicit conversions (strip). Not named ast.py: gencpp_driver.py runs by path
from this folder, where that name would hide the standard library's ast."""

from __future__ import annotations

import bisect
import ctypes
import re
from collections.abc import Callable
from typing import TypeAlias

import clang.cindex as ci

from archlog.values import Value, concat

K = ci.CursorKind
SKIP = (K.TYPE_REF, K.NAMESPACE_REF, K.TEMPLATE_REF)
# what the walkers key declarations by: (file, line, column), None for a cursor without a file
CursorKey: TypeAlias = tuple | None
# ROS 2 interfaces: pkg::msg::Name, pkg::srv::Name_Request_<...>, pkg::action::Name_Goal_<...>
ROS2_TYPE = re.compile(r"\b(\w+)::(msg|srv|action)::([A-Z][A-Za-z0-9]*)")
MSG_TYPE = re.compile(r"\b(\w+)::(\w+?)(?:Request|Response)?_<")
PLAIN_TYPE = re.compile(r"\b(?!std\b|boost\b|ros\b|message_filters\b|actionlib\b)(\w+)::(\w+?)"
                        r"(?:Request|Response)?(?:::(?:Const)?Ptr|ConstPtr)?\b")


def qualified(cursor: ci.Cursor | None) -> str:
    """ns::Class of a declaration (template specialisations reduced to the template's name)."""
    parts = []
    while cursor is not None and cursor.kind != K.TRANSLATION_UNIT:
        if cursor.spelling:
            parts.append(cursor.spelling)
        cursor = cursor.semantic_parent
    return "::".join(reversed(parts))


def template_arg_type(call: ci.Cursor) -> str | None:
    callee = next(call.get_children(), None)
    if callee is None:
        return None
    return next((t for c in callee.get_children() if c.kind == K.TYPE_REF and (t := ros_type(c.type))), None)


PCL_CLOUD = re.compile(r"\bpcl::PointCloud<")
"""A pcl::PointCloud<T> travels as sensor_msgs/PointCloud2 (pcl_ros's serialization)."""


def ros_type(type_: ci.Type) -> str | None:
    """'sensor_msgs/LaserScan' from a C++ type such as const sensor_msgs::LaserScan::ConstPtr&."""
    canonical = type_.get_canonical().spelling
    if (ros2 := ros2_type(canonical)) is not None:
        return ros2
    if PCL_CLOUD.search(canonical):
        return "sensor_msgs/PointCloud2"
    match = MSG_TYPE.search(canonical)
    if match:
        return action_base(f"{match.group(1)}/{match.group(2)}")
    return type_from_spelling(canonical) or type_from_spelling(type_.spelling)


def ros2_type(spelling: str) -> str | None:
    """'std_msgs/msg/String' from std_msgs::msg::String_<...>, pkg::srv::Name_Request, pkg::action::Name."""
    match = ROS2_TYPE.search(spelling)
    return "/".join(match.groups()) if match else None


def type_from_spelling(spelling: str) -> str | None:
    if (ros2 := ros2_type(spelling)) is not None:
        return ros2
    if PCL_CLOUD.search(spelling):
        return "sensor_msgs/PointCloud2"
    match = MSG_TYPE.search(spelling)
    if match:
        return action_base(f"{match.group(1)}/{match.group(2)}")
    inner = spelling.replace("const ", "")
    if "<" in inner:
        inner = inner[inner.index("<") + 1:]
    match = PLAIN_TYPE.search(inner)
    return action_base(f"{match.group(1)}/{match.group(2)}") if match else None


def action_base(type_name: str) -> str:
    """An action's messages are named after it: pkg/FooAction -> pkg/Foo."""
    return type_name[: -len("Action")] if type_name.endswith("Action") else type_name


def camera_info(topic: Value) -> Value:
    """image_transport's camera_info topic: a sibling of the image topic."""
    if isinstance(topic, str):
        parent = topic.rsplit("/", 1)[0] if "/" in topic.strip("/") else ("/" if topic.startswith("/") else "")
        return f"{parent}/camera_info" if parent not in ("", "/") else f"{parent}camera_info"
    return concat(topic, "/../camera_info")


def period(hz: str) -> str:
    try:
        return repr(1 / float(hz))
    except (ValueError, ZeroDivisionError):
        return f"1/{hz}"


def is_rvalue(expr: ci.Cursor) -> bool:
    """A literal or temporary, not a variable the parameter could be stored into."""
    return not any(c.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR) for c in expr.walk_preorder())


def written_args(call: ci.Cursor) -> list[ci.Cursor]:
    """The call's arguments as written (default arguments have no location)."""
    return [a for a in call.get_arguments() if a.location.file is not None]


def unquote(literal: str) -> str:
    body = literal[literal.index('"') + 1: literal.rindex('"')] if '"' in literal else literal
    return body.encode("utf-8").decode("unicode_escape", errors="replace") if "\\" in body else body


def default_constructed(init: ci.Cursor) -> bool:
    """`std::string s;` has a constructor call with no arguments as its 'initialiser'."""
    return init.kind == K.CALL_EXPR and not written_args(init)


def assignments(decl: ci.Cursor) -> list[ci.Cursor] | None:
    """The right-hand sides assigned to a variable in its scope (if/else branches give several),
    or None when it is also changed otherwise (`+=`, passed by reference)."""
    scope = decl.semantic_parent
    if scope is None:
        return None
    found: list[ci.Cursor] = []
    for cursor in scope.walk_preorder():
        if cursor.kind in (K.BINARY_OPERATOR, K.CALL_EXPR, K.COMPOUND_ASSIGNMENT_OPERATOR) and \
                cursor.spelling in ("operator=", "operator+=", "=", "+="):
            operands = [c for c in cursor.get_children() if not (c.kind == K.UNEXPOSED_EXPR and
                                                                  c.spelling.startswith("operator"))]
            refs = [c for c in cursor.walk_preorder() if c.kind in (K.DECL_REF_EXPR, K.MEMBER_REF_EXPR)]
            if refs and refs[0].referenced == decl:
                if "+=" in cursor.spelling or len(operands) < 2:
                    return None
                found.append(operands[-1])
    return found


# clang's operator kinds (CXBinaryOperatorKind, CXUnaryOperatorKind), by position
_BINARY = ("", ".*", "->*", "*", "/", "%", "+", "-", "<<", ">>", "<=>", "<", ">", "<=", ">=", "==", "!=", "&", "^",
           "|", "&&", "||", "=", "*=", "/=", "%=", "+=", "-=", "<<=", ">>=", "&=", "^=", "|=", ",")
_UNARY = ("", "++", "--", "++", "--", "&", "*", "+", "-", "~", "!", "__real", "__imag", "__extension__", "co_await")


def _operator_kind(name: str) -> Callable[[ci.Cursor], int] | None:
    """libclang's clang_getCursor{Binary,Unary}OperatorKind (libclang 17 and later), else None."""
    try:
        function = getattr(ci.conf.lib, name)
    except AttributeError:
        return None
    function.argtypes, function.restype = [ci.Cursor], ctypes.c_int
    return function


_BINARY_KIND = _operator_kind("clang_getCursorBinaryOperatorKind")
_UNARY_KIND = _operator_kind("clang_getCursorUnaryOperatorKind")


def binary_operator(expr: ci.Cursor) -> str:
    """The operator of a BINARY_OPERATOR or COMPOUND_ASSIGNMENT_OPERATOR cursor ("=", "&&", "==")."""
    if _BINARY_KIND is not None:
        kind = _BINARY_KIND(expr)
        return _BINARY[kind] if 0 < kind < len(_BINARY) else ""
    children = list(expr.get_children())
    if not children:
        return ""
    end = children[0].extent.end.offset
    return next((t.spelling for t in expr.get_tokens() if t.extent.start.offset >= end), "")


def unary_operator(expr: ci.Cursor) -> str:
    """The operator of a UNARY_OPERATOR cursor ("!", "++", "*", "&", "-")."""
    if _UNARY_KIND is not None:
        kind = _UNARY_KIND(expr)
        return _UNARY[kind] if 0 < kind < len(_UNARY) else ""
    words = [t.spelling for t in expr.get_tokens()]
    return words[0] if words and not words[0][0].isalnum() else words[-1] if words else ""


CALL_WINDOW = 1024
"""Characters after a call's start that the token fallback reads for its arguments."""


def line_finder(text: str) -> Callable[[int], int]:
    """The line of an offset in `text`, by bisecting its newlines (each call O(log n), where
    counting the newlines before every match of a file would be quadratic)."""
    newlines = [m.start() for m in re.finditer("\n", text)]
    return lambda offset: bisect.bisect_left(newlines, offset) + 1


_COMMENT_OR_LITERAL = re.compile(r'"(?:[^"\\\n]|\\.)*"|\'(?:[^\'\\\n]|\\.)*\'|//[^\n]*|/\*.*?(?:\*/|\Z)', re.S)


def blank_comments(text: str) -> str:
    """`text` with its comments turned into spaces (newlines kept, so offsets and lines do not
    move), string and character literals left as they are: a call in a comment is not code."""
    return _COMMENT_OR_LITERAL.sub(
        lambda m: m.group() if m.group()[0] in "\"'" else re.sub(r"[^\n]", " ", m.group()), text)


def strip(expr: ci.Cursor) -> ci.Cursor:
    """Below implicit conversions, parentheses and temporaries to the expression as written."""
    while expr.kind in (K.UNEXPOSED_EXPR, K.PAREN_EXPR, K.CXX_FUNCTIONAL_CAST_EXPR, K.CSTYLE_CAST_EXPR,
                        K.CXX_STATIC_CAST_EXPR):
        children = [c for c in expr.get_children() if c.kind not in SKIP]
        if len(children) != 1:
            break
        expr = children[0]
    return expr
