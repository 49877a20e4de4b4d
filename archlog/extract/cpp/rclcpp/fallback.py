"""rclcpp calls read from the text of lines where libclang's AST is incomplete (headers missing):
entity and action calls, their QoS, and the node's name."""

from __future__ import annotations

import re
from fractions import Fraction

import clang.cindex as ci

from archlog import sandbox
from archlog.extract.cpp.cache import cache_dir
from archlog.extract.cpp.clang_ast import CALL_WINDOW, line_finder, type_from_spelling, unquote
from archlog.extract.cpp.rclcpp.api import ENTITIES
from archlog.extract.cpp.rclcpp.context import WalkContext
from archlog.extract.cpp.rclcpp.durations import CHRONO_LITERAL, CHRONO_UNITS
from archlog.extract.cpp.stubs import API_DIR
from archlog.extract.qos import PRESET_NAMES, Qos, seconds_text
from archlog.extract.summary import Port
from archlog.values import Unknown, Value


def ros2_fallback(ctx: WalkContext, text: str, covered: set[int], tu: ci.TranslationUnit) -> None:
    """Read rclcpp entity calls, action servers/clients and the node's name from the text of
    lines where the AST produced nothing (type aliases from the file and the workspace headers
    it includes)."""
    aliases = type_aliases([text, *workspace_header_texts(tu)])
    sub_nodes = {m.group(1): unquote(m.group(2)) for m in re.finditer(
        r"(\w+)\s*=\s*(?:this\s*->\s*)?create_sub_node\s*\(\s*(\"[^\"]*\")", text)}
    line_of = line_finder(text)
    for match in [*_ENTITY_FALLBACK.finditer(text), *_ACTION_FALLBACK.finditer(text)]:
        line = line_of(match.start())
        if line in covered or (ctx.spans is not None and not any(a <= line <= b for a, b in ctx.spans)):
            continue
        method, template, first = match.group("method", "type", "name")
        obj = match.group("obj") if "obj" in match.re.groupindex else None
        kind = ENTITIES[method] if match.re is _ENTITY_FALLBACK else \
            ("action_server" if method == "create_server" else "action_client")
        name: Value = unquote(first) if first.startswith('"') else \
            Unknown(f"{first} (read from tokens)", ctx.file, line)
        type_: Value = type_from_spelling(aliases.get(template, template)) or \
            Unknown(f"{method}<{template}> (type not readable without the AST)", ctx.file, line)
        qos: tuple[tuple[str, str], ...] = ()
        if kind in ("publisher", "subscriber"):
            qos = text_qos(_next_argument(text, match.end()))
        ctx.result.ports.append(Port(kind, name, type_, ctx.file, line, 0, sub_nodes.get(obj or "", ""),
                                      qos=qos))
        ctx.result.fallback_lines.append(line)
    for named in _NODE_FALLBACK.finditer(text) if ctx.result.default_name is None else []:
        line = line_of(named.start())
        if ctx.spans is None or any(a <= line <= b for a, b in ctx.spans):
            ctx.result.default_name = unquote(named.group(1))
            ctx.result.name_file, ctx.result.name_line = ctx.file, line
            break


_ENTITY_FALLBACK = re.compile(
    r"(?:\b(?P<obj>\w+)\s*(?:\.|->)\s*)?(?<!::)\b(?P<method>create_publisher|create_subscription|create_service|"
    r"create_client)\s*<\s*(?P<type>[\w:]+)[^>;]*>\s*\(\s*(?P<name>\"(?:[^\"\\]|\\.)*\"|[\w:.>\-]+)")


_ACTION_FALLBACK = re.compile(
    r"\brclcpp_action::(?P<method>create_server|create_client)\s*<\s*(?P<type>[\w:]+)[^>;]*>\s*\(\s*[^,;]+?,\s*"
    r"(?P<name>\"(?:[^\"\\]|\\.)*\"|[\w:.>\-]+)")


_ALIAS = re.compile(r"\busing\s+(\w+)\s*=\s*(?:typename\s+)?([\w:]+)\s*;|\btypedef\s+([\w:]+)\s+(\w+)\s*;"
                    r"|\busing\s+((?:\w+::)+(\w+))\s*;")


_NODE_FALLBACK = re.compile(r"[:,]\s*(?:rclcpp::Node|Node|(?:rclcpp_lifecycle::)?LifecycleNode)\s*\(\s*(\"[^\"]+\")")


def type_aliases(texts: list[str]) -> dict[str, str]:
    """`using X = a::b::C;`, `typedef a::b::C X;` and `using a::b::C;` in C++ texts: name -> type."""
    found: dict[str, str] = {}
    for text in texts:
        for m in _ALIAS.finditer(text):
            found.setdefault(m.group(1) or m.group(4) or m.group(6), m.group(2) or m.group(3) or m.group(5))
    return found


def workspace_header_texts(tu: ci.TranslationUnit) -> list[str]:
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
        if "KeepAll" in inner:
            qos.initialise("keep_all", None, text)
        elif last is not None:
            qos.initialise("keep_last", last.group(1) or last.group(2), text)
        else:
            return Qos.unknown(text).facts()
    for method, argument in re.findall(r"\.\s*(\w+)\s*\(([^()]*(?:\([^()]*\))?[^()]*)\)", text[head.end():]):
        argument = argument.strip()
        if method in ("deadline", "lifespan", "liveliness_lease_duration"):
            literal = CHRONO_LITERAL.match(argument.replace(" ", ""))
            qos.apply(method, seconds_text(Fraction(literal.group(1)) * CHRONO_UNITS[literal.group(2)])
                      if literal else None, text)
        elif not qos.apply(method, argument or None, text):
            qos.unread.append(text)
    return qos.facts()
