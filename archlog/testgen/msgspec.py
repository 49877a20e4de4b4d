"""Message definitions (.msg) as plain data for strategies: fields with their base type and array
shape, and constants. Definitions come from archlog's message index (the workspace's packages and
the installed share dirs); a line that does not parse is a diagnostic with its file and line, and
its field is left out.

ROS 2 types are named `pkg/msg/Name` and looked up as `pkg/Name` (the installed share dirs may be
ROS 1's: the common definitions are the same). Their nested types are named the ROS 2 way,
`time`/`duration` are builtin_interfaces' Time/Duration, a Header has no `seq`, and the ROS 2
syntax is read: bounded strings and arrays (`string<=N`, `T[<=N]`, their bound kept in "bounds")
and default values after the field name."""

from __future__ import annotations

import re

from archlog import sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace.index import Workspace
from archlog.extract.workspace.messages import message_files

BUILTIN = ("bool", "byte", "char", "int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64",
           "float32", "float64", "string", "time", "duration")
_FIELD = re.compile(r"^(?P<type>[A-Za-z][\w/]*)(?:<=(?P<strbound>\d+))?"
                    r"(?P<array>\[(?P<bounded><=)?(?P<size>\d*)\])?\s+(?P<name>[A-Za-z]\w*)"
                    r"(?:\s*=\s*(?P<value>.*)|\s+(?P<default>\S.*))?$")
ROS2_TIME = {"fields": [["sec", "int32", None], ["nanosec", "uint32", None]], "constants": {}}
ROS2_BUILTIN = {"builtin_interfaces/msg/Time": ROS2_TIME, "builtin_interfaces/msg/Duration": ROS2_TIME,
                "std_msgs/msg/Header": {"fields": [["stamp", "builtin_interfaces/msg/Time", None],
                                                   ["frame_id", "string", None]], "constants": {}}}

# type -> {"fields": [[name, base type, array size (None: scalar, -1: variable)]],
#          "constants": {name: [base type, value]}, "bounds": {name: longest string or array} (if any)}
Specs = dict[str, dict]


def message_specs(workspace: Workspace, types: dict[str, tuple[str, int]], diagnostics: DiagnosticSink) -> Specs:
    """The definitions of `types` (each with the file and line of a port using it; a service type's is
    its request's, an action type's its goal's) and of every message type nested in them; a type without a definition is a
    diagnostic there (its topic gets no strategy)."""
    files = message_files(workspace)
    specs: Specs = {}
    todo = list(types.items())
    while todo:
        name, where = todo.pop()
        if name in specs or name in BUILTIN:
            continue
        if name in ROS2_BUILTIN:
            specs[name] = ROS2_BUILTIN[name]
            continue
        kind_path = files.get(name) or files.get(re.sub(r"/(msg|srv|action)/", "/", name))
        if kind_path is None:
            diagnostics.add(*where, "testgen-message", f"no definition found for message type {name}")
            specs[name] = {"fields": [], "constants": {}, "missing": True}
            continue
        path = kind_path[1]
        try:
            text = sandbox.read_text(path, "message")
        except sandbox.Refused as exc:
            diagnostics.add(workspace.display(path), 1, exc.code, f"not read: {exc}", "warning")
            specs[name] = {"fields": [], "constants": {}, "missing": True}
            continue
        shown = workspace.display(path)
        if kind_path[0] != "msg":  # a service's request, an action's goal: the part before the separator
            text = re.split(r"^---\s*$", text, maxsplit=1, flags=re.MULTILINE)[0]
        specs[name] = parse_msg(text, name.split("/")[0], shown, diagnostics, ros2=bool(re.search(r"/(msg|srv|action)/", name)))
        todo += [(base, (shown, 1)) for _n, base, _a in specs[name]["fields"] if base not in BUILTIN]
    return specs


def parse_msg(text: str, package: str, shown: str, diagnostics: DiagnosticSink, ros2: bool = False) -> dict:
    """One .msg file: fields (nested types made `pkg/Name`, or `pkg/msg/Name` for ROS 2; `Header` is
    std_msgs') and constants."""
    fields: list[list] = []
    constants: dict[str, list] = {}
    bounds: dict[str, int] = {}
    for number, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip() if "=" not in raw.split("#", 1)[0] else raw.strip()
        if not line:
            continue
        found = _FIELD.match(line)
        if not found:
            diagnostics.add(shown, number, "testgen-message", f"not a field or constant: {line!r}", "warning")
            continue
        base = _qualified(found["type"], package, ros2)
        if found["value"] is not None:
            value = found["value"] if base == "string" else found["value"].split("#", 1)[0].strip()
            constants[found["name"]] = [base, _constant(base, value)]
            continue
        size = None if not found["array"] else int(found["size"]) if found["size"] and not found["bounded"] else -1
        fields.append([found["name"], base, size])
        if found["bounded"] or found["strbound"]:
            bounds[found["name"]] = int(found["size"] if found["bounded"] else found["strbound"])
    return {"fields": fields, "constants": constants, **({"bounds": bounds} if bounds else {})}


def _qualified(name: str, package: str, ros2: bool = False) -> str:
    if ros2 and name in ("time", "duration"):
        return f"builtin_interfaces/msg/{name.capitalize()}"
    if name in BUILTIN:
        return name
    if name == "Header":
        return "std_msgs/msg/Header" if ros2 else "std_msgs/Header"
    if ros2:
        pkg, _, short = name.rpartition("/")
        return f"{pkg or package}/msg/{short}" if "/msg/" not in name else name
    return name if "/" in name else f"{package}/{name}"


def _constant(base: str, value: str) -> object:
    if base == "string":
        return value
    if base == "bool":
        return value.lower() in ("true", "1")
    try:
        return float(value) if base.startswith("float") else int(value, 0)
    except ValueError:
        return value
