"""Type adaptation (rclcpp::TypeAdapter, REP 2007): a publisher or subscription of a custom C++
type that a TypeAdapter specialisation maps onto a ROS message carries that message on the wire
(`RCLCPP_USING_CUSTOM_TYPE_AS_ROS_MESSAGE_TYPE(vision::CvImage,
sensor_msgs::msg::Image)`): the port's type is the message, as the graph shows it."""

from __future__ import annotations

import re
from dataclasses import replace

from archlog.extract.cpp.clang_ast import type_from_spelling
from archlog.extract.summary import Port

_ADAPTER = re.compile(r"\bRCLCPP_USING_CUSTOM_TYPE_AS_ROS_MESSAGE_TYPE\s*\(\s*([\w:]+)\s*,\s*([\w:]+)\s*\)"
                      r"|\bTypeAdapter\s*<\s*([\w:]+)\s*,\s*([\w:]+)\s*>")
_INTERFACE = re.compile(r"^\w+/(?:msg|srv|action)/\w+$")


def not_interfaces(ports: list[Port]) -> bool:
    """Whether some topic port has a known type that is no ROS 2 interface (a custom C++ type)."""
    return any(isinstance(p.type, str) and p.type and not _INTERFACE.match(p.type)
               for p in ports if p.kind in ("publisher", "subscriber"))


def adapters(texts: list[str]) -> dict[str, str]:
    """Custom type (as a port renders it) -> the ROS message its TypeAdapter gives, from C++ texts."""
    found: dict[str, str] = {}
    for text in texts:
        for match in _ADAPTER.finditer(text):
            custom, message = (match.group(1), match.group(2)) if match.group(1) else (match.group(3), match.group(4))
            if (shown := type_from_spelling(custom)) and (ros := type_from_spelling(message)):
                found.setdefault(shown, ros)
    return found


def adapted(ports: list[Port], types: dict[str, str]) -> list[Port]:
    """The ports, a publisher's or subscription's adapted custom type replaced by its ROS message."""
    return [replace(p, type=types[p.type]) if p.kind in ("publisher", "subscriber") and isinstance(p.type, str)
            and p.type in types else p for p in ports]
