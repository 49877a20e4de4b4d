"""Hand-written YAML node models for nodes without source, and external producers/consumers.

A model file holds one model or a list under `models:`. Each model names `package` and `executable`
(or `instance`, the resolved name of an external node that is always part of the configuration) and
lists its ports. A name may be a string or `{param: NAME, default: VALUE}`; `{each: LIST_PARAM,
field: KEY}` makes one port per element of a list parameter (twist_mux's inputs), `{file: PARAM,
key: KEY, field: FIELD}` one per element of the list KEY in the YAML file PARAM names
(yocs_cmd_vel_mux's inputs; system/param_files.py); a port with `if: {param: NAME, default: VALUE}`
exists only when that parameter is true (or equals `equals`), and with `if: {param: NAME, set:
true}` only when the configuration sets it. A ROS 2 port may give `qos:` as a preset's name or as
`{preset: P, reliability: ..., depth: ..., deadline: SECONDS, ...}` (rmw's default profile when no
preset is named). An image port with `camera_info: true` is an image_transport camera subscriber or
publisher: its camera_info topic is the sibling of the image topic as resolved and remapped
(system/link.py). `plugins:` lists where a node loads pluginlib classes its parameters choose (see
`PluginSlot`), and a file's `classes:` the ports such a class creates in the namespace its host
gives it (system/plugin_slots.py). A model with `incomplete: REASON` lists only some ports, so its
nodes count as opaque. A name `{argv: "{1}_select", default: ...}` or `{argv_from: 2}`, a
type `{argv: "{3}"}` or `*` (whatever the topic carries), and a condition `{option: [-p, --publish]}`
or `{argv: "{1}", equals: pub}` come from each instance's command line (topic_tools' relays,
rostopic: `argv_ports`; `valued_options` are the options whose value is no positional word); a
type `{like: NAME}` is the type the system's publishers of topic NAME give (a relay's output:
facts/followed_types.py). A port with `since: VERSION` (or a list, one per release line) exists
only in those releases of the package, checked against the version the configuration uses
(package.xml; else the newest release of the line the model's `distros` gives for ROS_DISTRO:
`released`); `optional: true` marks a subscriber the node works without. `tf_broadcasts` (with
`tf_description`, `tf_args`) says which transforms the node broadcasts, `tf_waits` which ones it
blocks for, and a port's or slot's `after_tf` which of those waits come before it. The format's
JSON Schema is archlog/models/model.schema.json; a file that breaks it is reported at the offending
entry's line and its valid models are still used.
"""

from __future__ import annotations

import json
import re
import shlex
import sys
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from fractions import Fraction
from functools import cache, lru_cache
from pathlib import Path
from typing import Any, TypeGuard

import jsonschema
import yaml

from archlog import budget, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.errors import ConfigError
from archlog.extract.launch import bounded_yaml
from archlog.extract.launch.model import Element
from archlog.extract.qos import DURATIONS, Qos, seconds_text
from archlog.extract.registry import Summaries
from archlog.extract.summary import NodeSummary, PluginSlot, Port, Transform, TransformWait
from archlog.extract.workspace.index import Workspace
from archlog.system.command_line import split_options
from archlog.values import ParamList, ParamRef, Unknown, Value

SECTIONS = {
    "publishers": "publisher", "subscribers": "subscriber",
    "services": "service_server", "service_clients": "service_client",
    "actions": "action_server", "action_clients": "action_client",
    "params": "param_read",
}
BUILTIN_DIR = Path(__file__).resolve().parent.parent / "models"
UNSET = "<not set>"  # the value of a `set: true` condition's parameter when the configuration lacks it


class _Lines:
    """Records each mapping's line as key '__line__'."""

    def construct_mapping(self, node: yaml.MappingNode, deep: bool = False) -> dict:
        mapping = super().construct_mapping(node, deep=deep)  # type: ignore[misc]
        mapping["__line__"] = node.start_mark.line + 1
        return mapping


class LineLoader(_Lines, bounded_yaml.BoundedLoader):
    """A YAML loader (within the budget) that records each mapping's line as key '__line__'."""


class ShippedLoader(_Lines, getattr(yaml, "CSafeLoader", yaml.SafeLoader)):  # type: ignore[misc]
    """archlog's own models (trusted, no budget needed) with libyaml's parser: ten times faster."""


@dataclass(frozen=True)
class PluginClass:
    """The ports a pluginlib class creates, as a model file's `classes:` entry lists them (names
    relative to the namespace the host gives the plugin)."""

    names: tuple[str, ...]
    ports: tuple[tuple[str, dict[str, Any]], ...]  # (port kind, the entry as written)
    reconfigure: bool
    file: str
    line: int


@dataclass
class NodeModels:
    """The models of one run: shipped ones (per executable, one per ROS version it is modelled
    for), the user's (which win over extracted summaries), external instances that models declare,
    and pluginlib classes by lookup name."""

    builtin: dict[tuple[str, str], list[NodeSummary]] = field(default_factory=dict)
    user: Summaries = field(default_factory=dict)
    externals: list[tuple[NodeSummary, str, Element]] = field(default_factory=list)
    classes: dict[str, PluginClass] = field(default_factory=dict)
    lines: dict[tuple[str, str], tuple[str, ...]] = field(default_factory=dict)  # shipped: the release lines described

    def shipped(self, kind: tuple[str, str], ros2: bool | None) -> NodeSummary | None:
        """The shipped model of an executable for a node on ROS 2 (True), on ROS 1 (False) or on
        either (None): a model of the other ROS version never applies."""
        wanted = None if ros2 is None else 2 if ros2 else 1
        return next((m for m in self.builtin.get(kind, []) if wanted is None or m.ros in (None, wanted)), None)


def load_node_models(paths: list[Path], workspace: Workspace, diagnostics: DiagnosticSink) -> NodeModels:
    """The shipped models and those in the user's files (a missing file is a ConfigError)."""
    models = NodeModels()
    version = cache(workspace.version)
    files = [(p, True) for p in sorted(BUILTIN_DIR.glob("*.yaml"))] + [(p, False) for p in paths]
    for index, (path, shipped) in enumerate(files, 1):
        if not path.is_file():
            raise ConfigError(f"model file not found: {path}")
        shown = workspace.display(path)
        loader = ShippedLoader if shipped else LineLoader
        lines = models.lines if shipped else None
        for summary, instance in load_models(path, shown, diagnostics, loader, models.classes, version, lines):
            if instance:
                line = summary.ports[0].line - 1 if summary.ports else 1
                element = Element(f"m{index:03d}{len(models.externals):03d}", shown, max(line, 1))
                models.externals.append((summary, instance, element))
            elif shipped:
                models.builtin.setdefault((summary.package, summary.executable), []).append(summary)
            else:
                models.user[(summary.package, summary.executable)] = summary
    return models


def load_models(path: Path, shown: str, diagnostics: DiagnosticSink, loader: type = LineLoader,
                classes: dict[str, PluginClass] | None = None,
                version: Callable[[str], str | None] | None = None,
                lines: dict[tuple[str, str], tuple[str, ...]] | None = None) -> list[tuple[NodeSummary, str | None]]:
    """(summary, external instance name or None) for every valid model in the file; its valid
    pluginlib classes go into `classes` by lookup name, the release lines a model's `distros` names into
    `lines` by executable. `version` gives a package's version, against which ports with `since` are
    kept or left out (without it, every port is kept)."""
    try:
        data = yaml.load(sandbox.read_text(path, "config"), Loader=loader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        diagnostics.add(shown, mark.line + 1 if mark else 1, "model-yaml", f"model file does not parse: {exc}", "error")
        return []
    except budget.BudgetExceeded as exc:
        diagnostics.add(shown, 1, "budget-exceeded", f"{exc}; the model file is not read", "error")
        return []
    except sandbox.Refused as exc:
        diagnostics.add(shown, 1, exc.code, f"cannot read model file: {exc}", "error")
        return []
    except UnicodeDecodeError:
        diagnostics.add(shown, 1, "model-read", "cannot read model file: not UTF-8", "error")
        return []
    if isinstance(data, dict) and "classes" in data:
        _classes(data, shown, diagnostics, {} if classes is None else classes)
    items = data.get("models", []) if isinstance(data, dict) and data.keys() & {"models", "classes"} else [data]
    if not isinstance(items, list):
        diagnostics.add(shown, data["__line__"], "model-schema", "invalid model file: models must be a list", "error")
        return []
    result = []
    for item in items:
        line = item.get("__line__", 1) if isinstance(item, dict) else 1
        problem = _schema_problem(item)
        if problem is not None:
            diagnostics.add(shown, problem[0] or line, "model-schema", f"invalid model: {problem[1]}", "error")
            continue
        instance = item.get("instance")
        summary = NodeSummary(str(item.get("package", "external")), str(item.get("executable", instance)), "model",
                              default_name=str(item.get("name", instance or item["executable"])),
                              incomplete=item.get("incomplete"), valued_options=tuple(item.get("valued_options", ())),
                              ros=item.get("ros") or ros_version(item))
        for section, kind in SECTIONS.items():
            for port in item.get(section) or []:
                if "since" not in port or version is None or \
                        released(_package_version(summary.package, item.get("distros") or {}, version), port["since"]):
                    _port(summary, kind, port, shown, diagnostics)
        summary.plugins = tuple(PluginSlot(str(slot.get("list", slot.get("param"))), str(slot["namespace"]),
                                           "list" in slot, _without_lines(slot.get("default")), shown,
                                           slot["__line__"], tuple(slot.get("after_tf", ())))
                                for slot in item.get("plugins") or [])
        _transforms(summary, item, shown, diagnostics)
        if lines is not None and item.get("distros"):
            lines[(summary.package, summary.executable)] = tuple(sorted({v for k, v in item["distros"].items()
                                                                        if k != "__line__"}))
        result.append((summary, instance))
    return result


_ROS2_TYPE = re.compile(r"^\w+/(msg|srv|action)/\w+$")
_ROS1_TYPE = re.compile(r"^\w+/\w+$")


def ros_version(item: dict) -> int | None:
    """The ROS version a model's port types are spelled for: 2 for pkg/msg/Type (srv, action), 1
    for pkg/Type; None when it gives no type, or both spellings."""
    types = {port["type"] for section in SECTIONS for port in item.get(section) or []
             if isinstance(port, dict) and isinstance(port.get("type"), str)}
    found = {2 if _ROS2_TYPE.match(t) else 1 for t in types if _ROS2_TYPE.match(t) or _ROS1_TYPE.match(t)}
    return found.pop() if len(found) == 1 else None


def _classes(data: dict, shown: str, diagnostics: DiagnosticSink, classes: dict[str, PluginClass]) -> None:
    """The file's valid `classes:` entries, by each of their lookup names."""
    entries = data["classes"] if isinstance(data["classes"], list) else []
    for entry in entries:
        problem = _schema_problem(entry, "pluginClass")
        if problem is not None:
            line = entry.get("__line__", data["__line__"]) if isinstance(entry, dict) else data["__line__"]
            diagnostics.add(shown, problem[0] or line, "model-schema", f"invalid plugin class: {problem[1]}", "error")
            continue
        lookup = entry["class"] if isinstance(entry["class"], list) else [entry["class"]]
        ports = tuple((kind, port) for section, kind in SECTIONS.items() for port in entry.get(section) or [])
        plugin = PluginClass(tuple(lookup), ports, bool(entry.get("reconfigure")), shown, entry["__line__"])
        classes.update(dict.fromkeys(lookup, plugin))


def _transforms(summary: NodeSummary, item: dict, shown: str, diagnostics: DiagnosticSink) -> None:
    """The model's tf keys: the transforms it broadcasts and those it waits for; a port or plugin slot
    whose `after_tf` names no wait of the model is reported."""
    summary.transforms = tuple(
        Transform(_name(t["parent"], shown, t["__line__"]), _name(t["child"], shown, t["__line__"]), shown,
                  t["__line__"], tuple(_name(a, shown, t["__line__"]) for a in t.get("after", ())),
                  None if "if" not in t else _condition(t["if"], shown))
        for t in item.get("tf_broadcasts") or [])
    summary.tf_waits = tuple(TransformWait(str(w["id"]), _name(w["target"], shown, w["__line__"]),
                                           _name(w["source"], shown, w["__line__"]), shown, w["__line__"],
                                           tuple(w.get("after_tf", ())))
                             for w in item.get("tf_waits") or [])
    summary.tf_declared = any(key in item for key in ("tf_broadcasts", "tf_description", "tf_args"))
    summary.tf_description = item.get("tf_description")
    summary.tf_args = bool(item.get("tf_args"))
    waits = {w.id for w in summary.tf_waits}
    marked = [(p.line, p.after_tf) for p in summary.ports] + [(s.line, s.after_tf) for s in summary.plugins] + \
        [(w.line, w.after_tf) for w in summary.tf_waits]
    for line, after in marked:
        for wait in sorted(set(after) - waits):
            diagnostics.add(shown, line, "model-schema", f"invalid model: after_tf names {wait}, which is not the id "
                            "of one of its tf_waits", "error")


def released(version: str | None, since: str | list[str]) -> bool:
    """Whether a port that exists `since` a release is in the package's `version` (unknown: it is, as
    models describe the newest release). A list names the first release with the port in each release
    line (major.minor) it was added or backported to; the newest one holds for every later release."""
    if version is None:
        return True
    have = _release(version)
    firsts = sorted(_release(first) for first in ([since] if isinstance(since, str) else since))
    return have >= firsts[-1] or any(have[:2] == first[:2] and have >= first for first in firsts)


def _release(version: str) -> tuple[int, ...]:
    """A version as numbers; `*` (the newest of a release line, `1.16.*`) above any number."""
    return tuple(sys.maxsize if n == "*" else int(n) for n in re.findall(r"[0-9]+|\*", version))


def _package_version(package: str, distros: dict[str, str], version: Callable[[str], str | None]) -> str | None:
    """The package's version (its package.xml), else the newest release of the release line the model's
    `distros` gives for the ROS distribution in use (ROS_DISTRO), else None."""
    found = version(package)
    line = distros.get(sandbox.getenv("ROS_DISTRO") or "")
    return found if found is not None or line is None else f"{line}.*"


def _port(summary: NodeSummary, kind: str, port: dict, shown: str, diagnostics: DiagnosticSink) -> None:
    if port.get("optional") and kind != "subscriber":
        diagnostics.add(shown, port["__line__"], "model-schema", "invalid model: optional marks a subscriber the node "
                        f"works without; a {kind.replace('_', ' ')} cannot be optional", "error")
        return
    if _per_instance(port):  # placed per instance (argv_ports)
        summary.argv_ports += ((kind, port, shown),)
        return
    line = port["__line__"]
    summary.ports += _ports(kind, port, shown, _name(port["name"], shown, line), *_typed(port.get("type", ""), [], shown, line))


def _ports(kind: str, port: dict, shown: str, name: Value, type_: Value, type_of: tuple[Value, ...] = ()) -> list[Port]:
    default = port.get("default")
    condition = port.get("if")
    private = isinstance(port["name"], dict) and port["name"].get("private")
    image = Port(kind, name, type_, shown, port["__line__"], 0, "~" if private else "",
                 None if default is None else str(default), qos=() if "qos" not in port else _qos(port["qos"]),
                 condition=None if condition is None or _argv_condition(condition) else _condition(condition, shown),
                 after_tf=tuple(port.get("after_tf", ())), type_of=type_of, optional=bool(port.get("optional")))
    if port.get("camera_info") and isinstance(name, str):  # placed beside the remapped image per instance
        return [image, replace(image, name="camera_info", type="sensor_msgs/CameraInfo", default=None, info_of=name)]
    return [image]


def _per_instance(port: dict) -> bool:
    """A port named, typed or conditioned by the instance's command line."""
    type_ = port.get("type")
    like = type_.get("like") if isinstance(type_, dict) else None
    return any(_from_argv(raw) for raw in (port.get("name"), type_, like)) or _argv_condition(port.get("if"))


def _from_argv(raw: object) -> bool:
    return raw == "*" or isinstance(raw, dict) and bool(raw.keys() & {"argv", "argv_from"})


def _argv_condition(condition: object) -> TypeGuard[dict]:
    return isinstance(condition, dict) and bool(condition.keys() & {"argv", "option", "never"})


def argv_ports(summary: NodeSummary, args: str) -> tuple[list[Port], list[Port]]:
    """A model's ports named, typed or conditioned by the command line, for an instance started with
    `args` (its positional words: remapping words, options and the values of `valued_options` left
    out, as ros::init, rospy.myargv and option parsers leave them out): those the instance has, and
    those whose command-line condition does not hold."""
    try:
        words = shlex.split(args)
    except ValueError:  # reported where the launch file is read
        words = []
    positional, _values = split_options(words, set(summary.valued_options))
    given = {word.split("=", 1)[0] for word in words if word.startswith("-") and ":=" not in word}
    present: list[Port] = []
    absent: list[Port] = []
    for kind, port, shown in summary.argv_ports:
        line = port["__line__"]
        typed = _typed(port.get("type", ""), positional, shown, line)
        ports = [p for name in _named(port["name"], positional, shown, line) for p in _ports(kind, port, shown, name, *typed)]
        condition = port.get("if")
        holds = not _argv_condition(condition) or _argv_holds(condition, positional, given)
        (present if holds else absent).extend(ports)
    return present, absent


def _named(raw: object, words: list[str], shown: str, line: int) -> list[Value]:
    """The names a model's name entry gives an instance whose positional words are `words`."""
    if isinstance(raw, dict) and "argv" in raw:
        return [_filled(raw["argv"], raw.get("default"), words, shown, line)]
    if isinstance(raw, dict) and "argv_from" in raw:
        return list(words[raw["argv_from"] - 1:])
    return [_name(raw, shown, line)]


def _typed(raw: object, words: list[str], shown: str, line: int) -> tuple[Value, tuple[Value, ...]]:
    """A port's type, and the topics whose publishers' type it carries (`like`; the type stays unknown
    until the system's publishers are known, facts/followed_types.py)."""
    if raw == "*":
        return Unknown("whatever the topic carries", shown, line), ()
    if isinstance(raw, dict) and "argv" in raw:
        return _filled(raw["argv"], None, words, shown, line), ()
    if isinstance(raw, dict):
        topics = tuple(_named(raw["like"], words, shown, line))
        return Unknown(f"the type of {', '.join(map(str, topics)) or 'no topic'}", shown, line), topics
    return str(raw), ()


def _argv_holds(condition: dict, words: list[str], given: set[str]) -> bool:
    """A command-line condition: one of the `option`s is given, or the positional word(s) `argv` names
    equal (one of) `equals`; `never` does not hold."""
    if "option" in condition:
        return bool(given & set(condition["option"]))
    if "argv" in condition:
        wanted = condition["equals"] if isinstance(condition["equals"], list) else [condition["equals"]]
        return _filled(condition["argv"], None, words, "", 0) in [str(w) for w in wanted]
    return False


def _filled(template: str, default: str | None, words: list[str], shown: str, line: int) -> Value:
    """A template with {N} replaced by the N-th word; `default` when a word it names is missing."""
    for text in (template, default):
        wanted = [int(n) for n in re.findall(r"\{([0-9]+)\}", text or "")]
        if text is not None and all(0 < n <= len(words) for n in wanted):
            return re.sub(r"\{([0-9]+)\}", lambda m: words[int(m.group(1)) - 1], text)
    return Unknown(f"command-line argument {template} not given", shown, line)


def _qos(spec: str | dict) -> tuple[tuple[str, str], ...]:
    """A ROS 2 port's QoS: a preset's name, or a preset (default: rmw's default) with policies changed."""
    if isinstance(spec, str):
        return Qos.preset(spec).facts()
    qos = Qos.preset(spec.get("preset", "default"))
    for policy, value in spec.items():
        if policy not in ("preset", "__line__"):
            text = seconds_text(Fraction(str(value))) if policy in DURATIONS else param_text(value)
            qos.apply(policy, text, f"{policy}: {value}")
    return qos.facts()


def _condition(condition: dict, shown: str) -> tuple[Value, str | None]:
    """(parameter read, value it must equal), or (parameter read, None) for `set: true`."""
    if condition.get("set"):
        return ParamRef(str(condition["param"]), UNSET, "", shown, condition["__line__"]), None
    return (ParamRef(str(condition["param"]), param_text(condition.get("default", False)), "", shown,
                     condition["__line__"]), param_text(condition.get("equals", True)))


def param_text(value: object) -> str:
    """A parameter value as text, booleans as YAML and roslaunch write them."""
    return str(value).lower() if isinstance(value, bool) else str(value)


@lru_cache(maxsize=2)
def _validator(definition: str) -> jsonschema.protocols.Validator:
    schema = json.loads((BUILTIN_DIR / "model.schema.json").read_text())
    return jsonschema.Draft202012Validator(schema["$defs"][definition] | {"$defs": schema["$defs"]})


def _schema_problem(item: object, definition: str = "model") -> tuple[int, str] | None:
    """(line, message) of the first place a model (or another definition) breaks the schema, or None."""
    errors = sorted(_validator(definition).iter_errors(_without_lines(item)), key=lambda e: list(e.absolute_path))
    if not errors:
        return None
    error = errors[0]
    node, line = item, item.get("__line__", 0) if isinstance(item, dict) else 0
    for step in error.absolute_path:
        node = node[step] if isinstance(node, (dict, list)) else None
        if isinstance(node, dict):
            line = node.get("__line__", line)
    where = "/".join(map(str, error.absolute_path))
    return line, (f"{where}: " if where else "") + error.message


def _without_lines(data: object) -> object:
    if isinstance(data, dict):
        return {k: _without_lines(v) for k, v in data.items() if k != "__line__"}
    if isinstance(data, list):
        return [_without_lines(v) for v in data]
    return data


def _name(raw: object, shown: str, line: int) -> Value:
    if isinstance(raw, dict) and "file" in raw:
        default = raw.get("default")
        return ParamList(str(raw["file"]), str(raw.get("field", "")), shown, line, str(raw["key"]),
                         None if default is None else str(default))
    if isinstance(raw, dict) and "each" in raw:
        return ParamList(str(raw["each"]), str(raw.get("field", "")), shown, line)
    if isinstance(raw, dict) and "param" in raw:
        return ParamRef(str(raw["param"]), str(raw.get("default", "")), "", shown, line)
    return str(raw)
