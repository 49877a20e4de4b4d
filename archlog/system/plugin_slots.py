"""Ports of the pluginlib classes a node loads because its parameters name them: move_base's
planners (`~base_local_planner: dwa_local_planner/DWAPlannerROS`) and a costmap's layers
(`~global_costmap/plugins: [{name: obstacle_layer, type: costmap_2d::VoxelLayer}]`).

A node model's `plugins:` slots say where the node reads the class names (`PluginSlot`); a model
file's `classes:` entries say what each class creates in the namespace it is given (`PluginClass`).
A plugin named by a single parameter lives in NAMESPACE/its class name (pluginlib's
`ClassLoader::getName`), a list element in NAMESPACE/its `name`. A class without a model gets a
`plugin-no-model` note at the launch element, so the ports it may create are not silently lost.
A slot's `after_tf` marks every port of its plugins (the host loads them after those transform waits).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace
from typing import Any

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import LaunchConfig, LaunchNode
from archlog.extract.library_ports import reconfigure_ports
from archlog.extract.summary import PluginSlot, Port
from archlog.system.node_models import PluginClass, param_text
from archlog.values import Unknown

_ABSENT = object()


def plugin_ports(node: LaunchNode, slots: tuple[PluginSlot, ...], classes: dict[str, PluginClass],
                 config: LaunchConfig, diagnostics: DiagnosticSink) -> list[Port]:
    """The ports of every plugin the instance's parameters make it load."""
    ports = []
    for slot in slots:
        for namespace, class_name in _loaded(slot, node, config, diagnostics):
            plugin = classes.get(class_name)
            if plugin is None:
                diagnostics.add(node.elem.file, node.elem.line, "plugin-no-model",
                                f"{node.name} loads the pluginlib class {class_name} ({slot.param}), which has no "
                                "model (a `classes:` entry of a model file); the ports it creates are unknown")
                continue
            ports += [replace(port, after_tf=slot.after_tf) for port in _class_ports(plugin, namespace, node, config)]
    return ports


def _loaded(slot: PluginSlot, node: LaunchNode, config: LaunchConfig,
            diagnostics: DiagnosticSink) -> list[tuple[str, str]]:
    """(plugin namespace, class name) of each plugin the slot loads."""
    value = _param(slot.param, node, config)
    if isinstance(value, Unknown):
        diagnostics.add(node.elem.file, node.elem.line, "plugin-no-model",
                        f"{node.name} loads the pluginlib classes that {slot.param} names, which is not known "
                        f"statically ({value.expr}); the ports they create are unknown")
        return []
    if not slot.listed:
        class_name = str(slot.default if value is _ABSENT else value)
        return [(names.join(slot.namespace, re.split(r"/|::", class_name)[-1]), class_name)]
    entries = slot.default if value is _ABSENT else value
    if not isinstance(entries, list):
        return []
    return [(names.join(slot.namespace, str(entry["name"])), str(entry["type"])) for entry in entries
            if isinstance(entry, dict) and "name" in entry and "type" in entry
            and _holds(entry.get("if"), slot.namespace, node, config)]


def _class_ports(plugin: PluginClass, namespace: str, node: LaunchNode, config: LaunchConfig) -> list[Port]:
    ports = [Port(*port, plugin.file, plugin.line) for port in reconfigure_ports(namespace)] \
        if plugin.reconfigure else []
    for kind, entry in plugin.ports:
        line = entry.get("__line__", plugin.line)
        items = _items(entry.get("each"), namespace, node, config)
        if isinstance(items, Unknown):  # a port per word of a value not known statically
            type_ = entry["type"] if isinstance(entry["type"], str) else Unknown(items.expr, plugin.file, line)
            ports.append(Port(kind, Unknown(items.expr, plugin.file, line), type_, plugin.file, line))
            continue
        for item in items:
            def fill(text: str, item: str = item) -> str:
                return text.replace("{item}", item)

            if not _holds(entry.get("if"), namespace, node, config, fill):
                continue
            name = _chosen(entry["name"], namespace, node, config, fill)
            type_ = _chosen(entry["type"], namespace, node, config, fill)
            if isinstance(entry["type"], dict) and isinstance(type_, str):
                type_ = f"{entry['type'].get('prefix', '')}{type_}"
            if isinstance(name, str) and entry.get("in") != "node" and not name.startswith("~"):
                name = names.join(namespace, name)  # a global name stays global
            ports.append(Port(kind, name, type_, plugin.file, line))
    return ports


def _items(each: str | None, namespace: str, node: LaunchNode, config: LaunchConfig) -> list[str] | Unknown:
    """The words (or list elements) of parameter `each`; one empty item when there is none."""
    if each is None:
        return [""]
    value = _param(names.join(namespace, each), node, config)
    if isinstance(value, Unknown):
        return Unknown(f"each word of {names.join(namespace, each)} ({value.expr})", value.file, value.line)
    if isinstance(value, list):
        return [str(v) for v in value]
    return str(value).split() if isinstance(value, (str, int, float)) else []


def _chosen(spec: str | dict[str, Any], namespace: str, node: LaunchNode, config: LaunchConfig,
            fill: Callable[[str], str]) -> str | Unknown:
    """A literal (with {item} filled in), or a parameter of the plugin's namespace with its default."""
    if isinstance(spec, str):
        return fill(spec)
    value = _param(names.join(namespace, fill(spec["param"])), node, config)
    if isinstance(value, Unknown):
        return value
    return fill(str(spec.get("default", ""))) if value is _ABSENT else param_text(value)


def _holds(condition: dict[str, Any] | None, namespace: str, node: LaunchNode, config: LaunchConfig,
           fill: Callable[[str], str] = str) -> bool:
    """A condition on a parameter of the namespace: equal to `equals` (true), or an unknown value."""
    if condition is None:
        return True
    value = _param(names.join(namespace, fill(condition["param"])), node, config)
    value = condition.get("default", False) if value is _ABSENT else value
    return isinstance(value, Unknown) or param_text(value).lower() == param_text(condition.get("equals", True)).lower()


def _param(name: str, node: LaunchNode, config: LaunchConfig) -> object:
    """The configuration's value of a (private or relative) parameter of the node, or _ABSENT."""
    key = names.resolve(name, node.namespace, node.name)
    return config.params[key][0] if key in config.params else _ABSENT

