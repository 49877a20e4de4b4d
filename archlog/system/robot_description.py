"""Ports that a robot description creates: the gazebo_ros plugins in its `<gazebo>` elements.

The description is a parameter set from a URDF text (`textfile=`) or from a `command=` that runs
xacro; xacro files are expanded with the xacro library routed through archlog's restricted evaluator,
sandboxed reading and budgets (see `xacro_expand`; nothing in them is run), with `$(find pkg)`
answered from the workspace. The plugins run inside gzserver once
`spawn_model -param NAME` inserts the model, so their ports are given to that spawn_model instance,
and so are the transforms they broadcast (a plugin model's `transforms:`).
"""

from __future__ import annotations

import functools
import re
import shlex
import xml.dom.minidom
from dataclasses import dataclass
from pathlib import Path

import yaml

from archlog import names, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import Element, LaunchConfig, LaunchNode
from archlog.extract.library_ports import image_transport_ports, reconfigure_ports
from archlog.extract.summary import Port, Transform
from archlog.extract.workspace.index import Workspace
from archlog.system.command_line import split_options
from archlog.system.xacro_expand import Place, XacroFailure, expand, parse_xml
from archlog.values import Unknown

PLUGIN_MODELS = Path(__file__).resolve().parent.parent / "models" / "plugins"
KINDS = {"publishers": "publisher", "subscribers": "subscriber", "services": "service_server"}


@dataclass(frozen=True)
class PluginModel:
    """The ports a gazebo plugin creates, as archlog/models/plugins/*.yaml describe them."""

    filename: str
    elements: dict[str, str | None]  # SDF element -> default (a template over earlier elements; None: unknown)
    namespace: str  # template
    ports: tuple[tuple[str, str, str, str | None], ...]  # (kind, name template, type, element it needs true)
    transported: frozenset[str] = frozenset()  # name templates of images published through image_transport
    # (parent, child frame templates, element it needs true); None: what it broadcasts is not modelled
    transforms: tuple[tuple[str, str, str | None], ...] | None = None


@functools.cache
def plugin_models() -> dict[str, PluginModel]:
    """Every plugin model shipped in archlog/models/plugins/, by library file name."""
    found = {}
    for path in sorted(PLUGIN_MODELS.glob("*.yaml")):
        for entry in yaml.safe_load(path.read_text())["plugins"]:
            ports = [(KINDS[key], p["name"], p["type"], p.get("if")) for key in KINDS for p in entry.get(key, [])]
            ports += [(*port, None) for ns in entry.get("reconfigure", []) for port in reconfigure_ports(ns)]
            transported = frozenset(p["name"] for p in entry.get("publishers", []) if p.get("transport") == "image")
            transforms = None if "transforms" not in entry else \
                tuple((t["parent"], t["child"], t.get("if")) for t in entry["transforms"])
            found[entry["filename"]] = PluginModel(entry["filename"], dict(entry.get("elements") or {}),
                                                   entry.get("namespace", ""), tuple(ports), transported, transforms)
    return found


@dataclass(frozen=True)
class Description:
    """A robot description as XML, the files it was expanded from and the element that sets it."""

    doc: xml.dom.minidom.Document
    files: list[Path]
    elem: Element


def spawned_ports(node: LaunchNode, words: list[str], config: LaunchConfig, workspace: Workspace,
                  diagnostics: DiagnosticSink) -> list[Port]:
    """The plugin ports of the description `spawn_model -urdf -param NAME` inserts."""
    _positional, option = split_options(words, {"-param", "-robot_namespace"})
    if "-param" not in option:
        return []
    found = description(option["-param"], node, config, workspace, diagnostics)
    if found is None:
        return []
    return [port for plugin in found.doc.getElementsByTagName("plugin")
            for port in _plugin_ports(plugin, option.get("-robot_namespace"), found.files, found.elem, workspace,
                                      diagnostics)]


def spawned_transforms(node: LaunchNode, words: list[str], config: LaunchConfig, workspace: Workspace,
                       diagnostics: DiagnosticSink) -> list[Transform] | None:
    """The transforms the gazebo plugins of the description `spawn_model -param NAME` inserts
    broadcast, or None when some plugin's are not modelled."""
    _positional, option = split_options(words, {"-param", "-robot_namespace"})
    found = description(option["-param"], node, config, workspace, diagnostics) if "-param" in option else None
    if found is None:
        return None
    transforms = []
    for plugin in found.doc.getElementsByTagName("plugin"):
        model = plugin_models().get(plugin.getAttribute("filename"))
        if model is None or model.transforms is None:
            return None
        values = _element_values(model, plugin, option.get("-robot_namespace"))
        file, line = where(f'"{model.filename}"', found.files, found.elem, workspace)
        for parent, child, needs in model.transforms:
            frames = _fill(parent, values), _fill(child, values)
            if needs is not None and (values.get(needs) or "").lower() not in ("1", "true"):
                continue
            if frames[0] is None or frames[1] is None:
                return None
            transforms.append(Transform(frames[0], frames[1], file, line))
    return transforms


def description(param: str, node: LaunchNode, config: LaunchConfig, workspace: Workspace,
                diagnostics: DiagnosticSink) -> Description | None:
    """The robot description a node reads from parameter `param` (resolved in its namespace), or None
    (with a diagnostic) when the configuration does not set it or it cannot be read statically."""
    key = names.canonical(names.resolve(param, node.namespace, node.name))
    if key not in config.params:
        diagnostics.add(node.elem.file, node.elem.line, "robot-description",
                        f"{node.name} reads {key}, which this configuration does not set", "warning")
        return None
    value, elem = config.params[key]
    described = _expand(value, elem, workspace, diagnostics)
    if described is None:
        return None
    text, files = described
    try:
        doc = parse_xml(text)
    except Exception as exc:  # expat raises several types for broken XML
        diagnostics.add(elem.file, elem.line, "robot-description", f"robot description is not XML: {exc}", "warning")
        return None
    return Description(doc, files, elem)


def _expand(value: object, elem: Element, workspace: Workspace,
            diagnostics: DiagnosticSink) -> tuple[str, list[Path]] | None:
    """The description's XML text and the files it came from."""
    if isinstance(value, str):
        return value, []
    expr = value.expr if isinstance(value, Unknown) else ""
    try:
        words = shlex.split(expr[len("command: "):]) if expr.startswith("command: ") else []
    except ValueError:  # unbalanced quotes: reported below as a description not known statically
        words = []
    program = next((i for i, w in enumerate(words) if Path(w).name in ("xacro", "xacro.py")), None)
    source = next((w for w in words[(program or 0) + 1:] if ":=" not in w and not w.startswith("-")), None)
    if program is None or source is None:
        diagnostics.add(elem.file, elem.line, "robot-description",
                        f"robot description not known statically ({expr or value}); its gazebo plugins are not read",
                        "note")
        return None
    mappings = dict(w.split(":=", 1) for w in words[program + 1:] if ":=" in w and not w.startswith("_"))
    return _xacro(Path(source), mappings, workspace, elem, diagnostics)


def _xacro(source: Path, mappings: dict[str, str], workspace: Workspace, elem: Element,
           diagnostics: DiagnosticSink) -> tuple[str, list[Path]] | None:
    def at(place: Place) -> tuple[str, int]:
        file, line = place
        return (workspace.display(file), line or 1) if file else (elem.file, elem.line)

    try:
        expanded = expand(source, mappings, workspace.find)
    except XacroFailure as failure:
        for read, place in failure.unseen:
            diagnostics.add(*at(place), *sandbox.env_note(read))
        diagnostics.add(*at(failure.place), failure.code, str(failure))
        return None
    for read, place in expanded.unseen:
        diagnostics.add(*at(place), *sandbox.env_note(read))
    for name, place in dict.fromkeys(expanded.legacy):
        diagnostics.add(*at(place), "xacro-legacy", f"<{name}> calls the macro {name} without the xacro: prefix "
                        "(deprecated; xacro 2 leaves it unexpanded); archlog expands it")
    return expanded.text, expanded.files


def _plugin_ports(plugin: xml.dom.minidom.Element, robot_ns: str | None, files: list[Path], elem: Element,
                  workspace: Workspace, diagnostics: DiagnosticSink) -> list[Port]:
    library = plugin.getAttribute("filename")
    file, line = where(f'"{library}"', files, elem, workspace)
    model = plugin_models().get(library)
    if model is None:
        diagnostics.add(file, line, "plugin-no-model", f"gazebo plugin {library or '(no filename)'} has no model "
                        "in archlog/models/plugins/; the ports it creates are unknown")
        return []
    values = _element_values(model, plugin, robot_ns)

    def unknown(template: str) -> Unknown:
        missing = sorted(e for e in model.elements if "{" + e + "}" in template and values[e] is None)
        return Unknown(f"{library} without <{'>, <'.join(missing)}>", file, line)

    ns = _fill(model.namespace, values)
    ports = []
    for kind, template, type_, needs in model.ports:
        name = _fill(template, values)
        if name == "" or needs is not None and (values.get(needs) or "").lower() not in ("1", "true"):
            continue  # an element set empty, or a flag not set: the plugin does not advertise it
        resolved: str | Unknown = names.resolve(name, "/" + ns.strip("/"), "/gazebo") if name is not None \
            and ns is not None else unknown(template if name is None else model.namespace)
        ports.append(Port(kind, resolved, type_, file, line))
        if template in model.transported and isinstance(resolved, str):
            ports += [Port(*port, file, line) for port in image_transport_ports(resolved)]
    return ports


def _element_values(model: PluginModel, plugin: xml.dom.minidom.Element, robot_ns: str | None) -> dict[str, str | None]:
    """The plugin's SDF element values, the model's defaults for those not given."""
    values: dict[str, str | None] = {}
    for element, default in model.elements.items():
        given = robot_ns if element == "robotNamespace" and robot_ns is not None else _text(plugin, element)
        values[element] = given if given is not None else _fill(default, values)
    return values


def _fill(template: str | None, values: dict[str, str | None]) -> str | None:
    """A template over element values, None when it refers to an element whose value is unknown."""
    if template is None:
        return None
    parts = re.split(r"\{(\w+)\}", template)
    if any(values.get(p) is None for p in parts[1::2]):
        return None
    return "".join(p if i % 2 == 0 else values[p] or "" for i, p in enumerate(parts))


def _text(plugin: xml.dom.minidom.Element, tag: str) -> str | None:
    found = [e for e in plugin.childNodes if getattr(e, "tagName", None) == tag]
    return "".join(n.data for n in found[0].childNodes if n.nodeType == n.TEXT_NODE).strip() if found else None


def where(needle: str, files: list[Path], elem: Element, workspace: Workspace) -> tuple[str, int]:
    """The first line holding `needle` in the description's files, else the launch element."""
    for path in files:
        try:
            for number, line in enumerate(sandbox.read_text(path, "description").splitlines(), 1):
                if needle in line:
                    return workspace.display(path), number
        except sandbox.Refused:
            continue
    return elem.file, elem.line
