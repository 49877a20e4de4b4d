"""The pluginlib classes a ROS 2 node loads because its parameters name them, and the ports they create.

The convention of ROS 2 hosts (a planner server, a costmap, a navigator): a list parameter names the
plugins (`planner_plugins: [grid]`; a string parameter names one), and each name's `NAME.plugin`
parameter names its class (`grid.plugin: pkg::GridPlanner`, a pluginlib lookup name or C++ type).
The values are the configuration's (parameter files, launch parameters), else the defaults the
node's source declares.
The class is found through the plugin descriptions the workspace's packages export
(`Package.plugin_classes`), and its code is read like a nodelet's (analysis.py). The plugin is given
the host node, so its ports' names are relative to the host. A class that no description of the
workspace declares is reported, and the node's pluginlib loads stay holes (facts `plugin_hole`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import LaunchNode
from archlog.extract.launch.ros2_params import matches
from archlog.extract.registry import Summaries
from archlog.extract.summary import NodeSummary
from archlog.extract.workspace.index import Workspace
from archlog.values import Unknown


@dataclass(frozen=True)
class NamedPlugin:
    """One plugin a node's parameters make it load: its name, its class as the parameter names it,
    and the (package, C++ type) of that class in the workspace (None: not declared there)."""

    name: str
    param: str
    class_name: str
    kind: tuple[str, str] | None


def named_plugins(node: LaunchNode, summary: NodeSummary | None, workspace: Workspace) -> list[NamedPlugin]:
    """The plugins the node's parameters name: each string (or string of a list) parameter whose
    `NAME.plugin` is set."""
    if not node.ros2 or summary is None or not summary.plugin_loads:
        return []
    values = _parameter_values(node, summary)
    found = []
    for value in values.values():
        for name in value if isinstance(value, list) else [value]:
            class_name = values.get(f"{name}.plugin")
            if isinstance(name, str) and isinstance(class_name, str) and class_name:
                exe = workspace.plugin_class(class_name)
                found.append(NamedPlugin(name, f"{name}.plugin", class_name, exe.kinds[0] if exe else None))
    return found


def with_plugins(node: LaunchNode, summary: NodeSummary, summaries: Summaries, workspace: Workspace,
                 diagnostics: DiagnosticSink) -> NodeSummary:
    """The node's summary with the ports of the plugins its parameters name. Its pluginlib loads stop
    being holes when every named class was read (the loads of the plugins' own code stay)."""
    plugins = named_plugins(node, summary, workspace)
    if not plugins:
        return summary
    ports, loads, complete = list(summary.ports), [], True
    for plugin in plugins:
        read = summaries.get(plugin.kind) if plugin.kind else None
        if read is None:
            complete = False
            why = "whose code was not read" if plugin.kind else "which no plugin description of the workspace declares"
            diagnostics.add(node.elem.file, node.elem.line, "plugin-no-model",
                            f"{node.name} loads the pluginlib class {plugin.class_name} ({plugin.param}), {why}; "
                            "the ports it creates are unknown")
            continue
        ports += [port for port in read.ports if port not in ports]
        loads += [at for at in read.plugin_loads if at not in loads]
    kept = summary.plugin_loads if not complete else []
    return replace(summary, ports=ports, plugin_loads=[*kept, *(at for at in loads if at not in kept)])


def _parameter_values(node: LaunchNode, summary: NodeSummary) -> dict[str, object]:
    """The node's parameters by (dotted) name: the defaults its source declares, then the values the
    configuration gives it, the last one winning as in rcl."""
    values: dict[str, object] = {port.name: port.default for port in summary.ports
                                 if port.kind == "param_read" and isinstance(port.name, str)
                                 and port.default is not None and not isinstance(port.default, Unknown)}
    name = node.name or _source_name(node, summary)
    for pattern, dotted, value, _elem in node.parameters:
        if not pattern or (name and matches(pattern, name)):
            values[dotted] = value
    return values


def _source_name(node: LaunchNode, summary: NodeSummary) -> str:
    """The full name the node's code gives it, when the launch file does not (before the instances are
    completed, system/instances.py); "" when it is not known statically."""
    given = summary.default_name
    if not isinstance(given, str) or not given or not isinstance(summary.namespace, str):
        return ""
    return names.join(names.join("/", node.namespace or summary.namespace), given)
