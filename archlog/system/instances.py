"""Finish ROS 2 node instances once their sources are read: the name and namespace the code gives
when the launch file does not, and the parameters that reach each node."""

from __future__ import annotations

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import LaunchConfig, LaunchNode
from archlog.extract.launch.ros2_params import matches
from archlog.extract.summary import NodeSummary
from archlog.system.command_line import command_value


def complete_instances(config: LaunchConfig, summaries: dict[tuple[str, str], NodeSummary],
                       diagnostics: DiagnosticSink) -> None:
    """Give every node a full name (launch names and namespaces win over the source's, as
    `__node`/`__ns` remaps do), then place its ROS 2 parameters under that name."""
    for node in config.nodes:
        if not node.name or not node.namespace:
            _place(node, summaries.get(node.kind), diagnostics)
    for node in config.nodes:
        for pattern, dotted, value, elem in node.parameters:
            if not pattern or matches(pattern, node.name):
                config.params[f"{node.name}/{dotted}"] = (value, elem)


def _place(node: LaunchNode, summary: NodeSummary | None, diagnostics: DiagnosticSink) -> None:
    namespace = node.namespace
    if not namespace:
        source_ns = summary.namespace if summary is not None else ""
        namespace = names.join("/", source_ns) if isinstance(source_ns, str) else "/"
        if not isinstance(source_ns, str):
            diagnostics.add(node.elem.file, node.elem.line, "node-name", f"the namespace {node.kind[1]} gives itself "
                            "is not known statically; using the root namespace", "note")
    base = node.name.rsplit("/", 1)[-1] if node.name else _source_name(node, summary, diagnostics)
    node.namespace = namespace
    node.name = names.join(namespace, base)


def _source_name(node: LaunchNode, summary: NodeSummary | None, diagnostics: DiagnosticSink) -> str:
    """The node name the code gives, or the executable's when that is not known."""
    fallback = node.type.rsplit("::", 1)[-1]
    given = command_value(summary.default_name, node.args) if summary is not None and summary.default_name else None
    if isinstance(given, str) and given:
        return given  # as the code names it, with the instance's command-line arguments
    why = "has no source or model" if summary is None else "gives itself a name not known statically"
    diagnostics.add(node.elem.file, node.elem.line, "node-name", f"the launch file does not name this node and "
                    f"{'/'.join(node.kind)} {why}; using {fallback}", "note")
    node.name_unknown = True
    return fallback
