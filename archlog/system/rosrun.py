"""The configuration without a launch file: every executable runs once, as `rosrun` starts it."""

from __future__ import annotations

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import Element, LaunchConfig, LaunchNode
from archlog.extract.summary import NodeSummary
from archlog.extract.workspace.index import Workspace
from archlog.system.command_line import command_value


def rosrun_config(summaries: dict[tuple[str, str], NodeSummary], workspace: Workspace,
                  diagnostics: DiagnosticSink) -> LaunchConfig:
    """With no launch file: every executable is one instance under its default name, started by
    itself (standalone), on ROS 2 when its package is built with ament."""
    config = LaunchConfig()
    for index, ((pkg, exe), summary) in enumerate(sorted(summaries.items()), 1):
        executable = workspace.executable(pkg, exe)
        if executable is not None and executable.cls and not executable.standalone:
            continue  # a nodelet or component runs inside a manager, unless built as a program of its own
        source = executable.sources[0] if executable and executable.sources else None
        file = summary.name_file or (workspace.display(source) if source else pkg)
        elem = Element(f"x{index:05d}", file, summary.name_line or 1)
        given = command_value(summary.default_name, "") if summary.default_name is not None else None
        name = given if isinstance(given, str) and given else exe
        unknown = given is not None and not isinstance(given, str)
        if unknown:
            diagnostics.add(elem.file, elem.line, "node-name", f"node name of {pkg}/{exe} is not known statically; "
                            f"using the executable name {exe}", "note")
        namespace = names.join("/", summary.namespace) if isinstance(summary.namespace, str) else "/"
        package = workspace.packages.get(pkg)
        config.nodes.append(LaunchNode(elem, pkg, exe, names.join(namespace, name), namespace,
                                       ros2=package is not None and package.ament, standalone=True,
                                       name_unknown=unknown))
    return config
