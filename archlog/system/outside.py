"""Providers outside the configuration: modelled executables the configuration does not start but
that plausibly run beside it, and the names and types they would provide.

A modelled executable counts when the configuration does not run its package and either a package
the configuration runs depends on it (package.xml: a driver or library node the code is written
against), or the configuration is the one without a launch file (every executable by itself: it says
nothing about what runs beside them, so any modelled provider may). Its publishers, services and
action servers are resolved under their default node name in the root namespace, as `ros2 run` or
`rosrun` starts them. Rules read them (`outside_port`) to report a counterpart only such a node would
provide as a note rather than as a missing one.
"""

from __future__ import annotations

from dataclasses import dataclass

from archlog import names
from archlog.extract.launch.model import LaunchConfig
from archlog.extract.summary import NodeSummary
from archlog.extract.workspace.index import Workspace
from archlog.values import ParamRef

PROVIDING = ("publisher", "service_server", "action_server")
_SPELLING = {"publisher": "msg", "service_server": "srv", "action_server": "action"}


@dataclass(frozen=True)
class OutsidePort:
    """A name a modelled executable outside the configuration would provide."""

    kind: str
    name: str
    type: str
    provider: str  # package/executable


def outside_ports(workspace: Workspace, config: LaunchConfig,
                  models: dict[tuple[str, str], list[NodeSummary]]) -> list[OutsidePort]:
    """The names the modelled executables outside the configuration would provide (see the module)."""
    running = {node.pkg for node in config.nodes}
    open_config = bool(config.nodes) and all(node.standalone for node in config.nodes)
    wanted = set().union(*(p.depends for name, p in workspace.packages.items() if name in running))
    found: set[OutsidePort] = set()
    for (pkg, exe), summaries in models.items():
        if pkg in running or not (open_config or pkg in wanted):
            continue
        for summary in summaries:
            node = names.join("/", summary.default_name if isinstance(summary.default_name, str) else exe)
            for port in summary.ports:
                name = port.name.default if isinstance(port.name, ParamRef) else port.name
                if port.kind not in PROVIDING or not isinstance(name, str) or not name or \
                        not isinstance(port.type, str) or not port.type:
                    continue
                resolved = names.resolve(name, "/", node)
                found.update(OutsidePort(port.kind, resolved, spelled, f"{pkg}/{exe}")
                             for spelled in spellings(port.type, port.kind))
    return sorted(found, key=lambda p: (p.kind, p.name, p.type, p.provider))


def spellings(type_: str, kind: str) -> tuple[str, ...]:
    """An interface's name as ROS 1 and ROS 2 spell it (`pkg/Type`, `pkg/msg/Type`): one interface
    of the same package and name, whichever spelling a model uses."""
    parts = type_.split("/")
    if len(parts) == 2:
        return type_, f"{parts[0]}/{_SPELLING[kind]}/{parts[1]}"
    if len(parts) == 3:
        return type_, f"{parts[0]}/{parts[2]}"
    return (type_,)
