"""The nodelet mechanism's own ports (nodelet 1.10, `nodelet/src/nodelet.cpp` and `loader.cpp`),
which no workspace holds the source of: a `nodelet manager` provides the services `~load_nodelet`,
`~unload_nodelet` and `~list` and, once a loader has bonded with it, publishes and subscribes
`~bond`; a `nodelet load TYPE MANAGER` process calls MANAGER/load_nodelet and MANAGER/unload_nodelet
and, unless `--no-bond`, publishes and subscribes MANAGER/bond under its own name. A `standalone`
process has none of these."""

from __future__ import annotations

import shlex

from archlog import names
from archlog.extract.launch.model import LaunchConfig, LaunchNode
from archlog.extract.summary import NodeSummary, Port

BOND = "bond/Status"
_SERVICES = (("load_nodelet", "nodelet/NodeletLoad"), ("unload_nodelet", "nodelet/NodeletUnload"),
             ("list", "nodelet/NodeletList"))


def _words(node: LaunchNode) -> list[str]:
    """The positional command-line words of a `nodelet` node (flags and remaps left out)."""
    try:
        return [w for w in shlex.split(node.args) if ":=" not in w] if node.args else []
    except ValueError:  # reported where the launch file is read
        return []


def _is_nodelet(node: LaunchNode, command: str) -> bool:
    return (node.pkg, node.type) == ("nodelet", "nodelet") and _words(node)[:1] == [command]


def is_manager(node: LaunchNode) -> bool:
    """A `nodelet manager` process."""
    return _is_nodelet(node, "manager")


def _bonded_manager(node: LaunchNode) -> str | None:
    """The full name of the manager a `nodelet load` process bonds with (None: not a bonded loader)."""
    words = _words(node)
    if not _is_nodelet(node, "load") or len(words) < 3 or "--no-bond" in words:
        return None
    return names.resolve(words[2], node.namespace, node.name)


def manager_summary(node: LaunchNode, config: LaunchConfig) -> NodeSummary:
    """What a `nodelet manager` process runs: its loader's ROS API, and its side of the bonds of
    the loaders that name it."""
    file, line = node.elem.file, node.elem.line
    ports = [Port("service_server", name, type_, file, line, handle_ns="~") for name, type_ in _SERVICES]
    ports.append(Port("param_read", "num_worker_threads", "", file, line, handle_ns="~", default="0"))
    if any(_bonded_manager(other) == node.name for other in config.nodes):
        ports += [Port(kind, "bond", BOND, file, line, handle_ns="~") for kind in ("publisher", "subscriber")]
    return NodeSummary("nodelet", "nodelet", "model", ports=ports)


def loader_ports(node: LaunchNode) -> list[Port]:
    """The ports a `nodelet load` process has besides its nodelet's: the manager's services it
    calls and its side of the bond."""
    words = _words(node)
    if not _is_nodelet(node, "load") or len(words) < 3:
        return []
    file, line, manager = node.elem.file, node.elem.line, words[2]
    ports = [Port("service_client", f"{manager}/{name}", type_, file, line) for name, type_ in _SERVICES[:2]]
    if _bonded_manager(node) is not None:
        ports += [Port(kind, f"{manager}/bond", BOND, file, line) for kind in ("publisher", "subscriber")]
    return ports
