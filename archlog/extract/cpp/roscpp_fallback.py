"""roscpp calls read from the text of lines where libclang's AST is incomplete (headers missing):
NodeHandle calls, the namespaces of their handles, their message types and named callbacks."""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import lru_cache

from archlog.extract.cpp.clang_ast import CALL_WINDOW, line_finder, type_from_spelling, unquote
from archlog.extract.cpp.handles import METHODS, NODE_HANDLE, NODELET_HANDLES
from archlog.extract.library_ports import reconfigure_ports
from archlog.extract.summary import Port
from archlog.values import Unknown, Value

_FALLBACK = re.compile(r"(\w+)\s*(?:\.|->)\s*(advertise|subscribe|advertiseService|serviceClient)\s*"
                       r"(?:<\s*([\w:\s]+?)\s*>)?\s*\(\s*(\"(?:[^\"\\]|\\.)*\"|\w+)")
# a dynamic_reconfigure server built on a handle (`new dynamic_reconfigure::Server<Config>(nh)`, or a
# variable `dynamic_reconfigure::Server<Config> server(nh)`): its Config header is generated at build time
_RECONFIGURE = re.compile(r"dynamic_reconfigure::Server\s*<[\w:\s]+>\s*(?:\w+\s*)?\(\s*(\w*)\s*\)")


def roscpp_fallback(text: str, file: str, covered: set[int],
                    spans: list[tuple[int, int]] | None) -> tuple[list[Port], list[tuple[str, Port]]]:
    """The ports of NodeHandle calls on lines of `text` (shown as `file`) that no port covers
    (within `spans`, if given), and the functions each call names (callback, port)."""
    ports: list[Port] = []
    named: list[tuple[str, Port]] = []
    handles = {m.group(1): unquote(m.group(2)) if m.group(2) else ""
               for m in re.finditer(r"NodeHandle\s+(\w+)\s*(?:\(\s*(\"[^\"]*\")\s*\))?", text)}
    objects = {m.group(1) for m in _FALLBACK.finditer(text)}
    handles.update({m.group(1): m.group(2) for m in re.finditer(r"[:,]\s*(\w+)\s*\(\s*\"(~?[\w/]*)\"\s*\)", text)
                    if m.group(1) in objects and m.group(1) not in handles})  # member initialisers
    handles.update({m.group(1): NODELET_HANDLES[m.group(2)] for m in re.finditer(
        r"NodeHandle\s*&?\s*(\w+)\s*=\s*(?:this\s*->\s*)?(get(?:MT)?(?:Private)?NodeHandle)\s*\(\s*\)", text)})
    line_of = line_finder(text)
    if spans is not None:
        spans = spans + _reached(text, spans, handles, line_of)
    for match in _RECONFIGURE.finditer(text):
        line = line_of(match.start())
        if line in covered or (spans is not None and not any(a <= line <= b for a, b in spans)):
            continue
        obj = match.group(1)
        server_ns: Value = "~" if not obj else handles[obj] if obj in handles else \
            Unknown(f"{obj} (read from tokens)", file, line)
        ports += [Port(kind, name, type_, file, line, 0, server_ns) for kind, name, type_ in reconfigure_ports("")]
    for match in _FALLBACK.finditer(text):
        line = line_of(match.start())
        if line in covered or (spans is not None and not any(a <= line <= b for a, b in spans)):
            continue
        obj, method, template, first = match.groups()
        kind = METHODS[(NODE_HANDLE, method)]  # every method _FALLBACK reads
        name: Value = unquote(first) if first.startswith('"') else \
            Unknown(f"{first} (read from tokens)", file, line)
        handle: Value = handles[obj] if obj in handles else Unknown(f"{obj} (read from tokens)", file, line)
        type_: Value = (type_from_spelling(template) if template else _callback_type(text, match.end())) or \
            Unknown(f"{obj}.{method} (type not readable without the AST)", file, line)
        port = Port(kind, name, type_, file, line, 0, handle)
        ports.append(port)
        named += [(callback, port) for callback in _argument_names(text, match.end())]
    return ports, named


_DEFINITION = re.compile(r"\b(?:\w+::)+(\w+)\s*\(([^()]*)\)\s*(?:const\s*)?\{")
_CALL = re.compile(r"(?:\.|->)\s*(\w+)\s*\(([^()]*)\)")


def _reached(text: str, spans: list[tuple[int, int]], handles: dict[str, str],
             line_of: Callable[[int], int]) -> list[tuple[int, int]]:
    """The spans of the file's other methods that the read code calls (`helper_->init(ph)`: a
    nodelet class handing its handle to an object of its own file), transitively; a NodeHandle
    parameter takes the namespace of the handle the call passes."""
    definitions: dict[str, list[tuple[int, int, str]]] = {}
    for match in _DEFINITION.finditer(text):
        end = _closing_brace(text, match.end() - 1)
        definitions.setdefault(match.group(1), []).append((line_of(match.start()), line_of(end), match.group(2)))
    found: list[tuple[int, int]] = []
    pending = list(spans)
    while pending and len(found) < 32:
        first, last = pending.pop()
        for call in _CALL.finditer(text):
            if not first <= line_of(call.start()) <= last:
                continue
            for start, end, params in definitions.get(call.group(1), []):
                if any(a <= start and end <= b for a, b in spans + found):
                    continue
                found.append((start, end))
                pending.append((start, end))
                for param, arg in zip(params.split(","), call.group(2).split(",")):
                    target = re.search(r"NodeHandle\s*&?\s*(\w+)\s*$", param)
                    if target and arg.strip() in handles:
                        handles[target.group(1)] = handles[arg.strip()]
    return found


def _closing_brace(text: str, opening: int) -> int:
    """The position of the brace that closes the one at `opening` (braces in strings count too)."""
    depth = 0
    for position in range(opening, len(text)):
        depth += {"{": 1, "}": -1}.get(text[position], 0)
        if depth == 0:
            return position
    return len(text) - 1


def _callback_type(text: str, start: int) -> str | None:
    """The message type of a callback named in a call's arguments, from the callback's own
    signature in the file text (for calls the AST lost)."""
    arguments = _call_text(text, start)
    callback = re.search(r"&\s*(?:\w+::)*(\w+)\s*[,)]", arguments)
    if callback is None:
        return None
    return _signature_type(text, callback.group(1))


@lru_cache(maxsize=128)
def _signature_type(text: str, function: str) -> str | None:
    """The message type of a callback's first parameter, from its signature in the text."""
    signature = re.search(rf"\b{function}\s*\(\s*(?:const\s+)?([\w:]+)", text)
    return type_from_spelling(signature.group(1)) if signature else None


def _call_text(text: str, start: int) -> str:
    """The rest of a call's statement from `start`, within CALL_WINDOW characters."""
    window = text[start: start + CALL_WINDOW]
    end = window.find(";")
    return window if end < 0 else window[:end]


def _argument_names(text: str, start: int) -> list[str]:
    """The names in a call's further arguments (`&Class::cb`, `cb`, `this`...), from the text."""
    arguments = _call_text(text, start)
    return re.findall(r",\s*&?\s*(?:\w+::)*([A-Za-z_]\w*)\s*(?=[,)])", arguments)
