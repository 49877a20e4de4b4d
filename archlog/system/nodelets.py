"""The nodelet mechanism's own ports (nodelet 1.10, `nodelet/src/nodelet.cpp` and `loader.cpp`),
which no workspace holds the source of: a `nodelet manager` provides the services `~load_nodelet`,
`~unload_nodelet` and `~list` and, once a loader has bonded with it, publishes and subscribes
`~bond`; a `nodelet load TYPE MANAGER` process calls MANAGER/load_nodelet and MANAGER/unload_nodelet
and, unless `--no-bond`, publishes and subscribes MANAGER/bond under its own name. A `standalone`
process has none of these.

An executable that loads nodelets into its own process (nodelet::Loader::load, as image_proc does)
has their ports: each nodelet's handles are in its own name's namespace (public) and under its name
(private), with the remappings the load was given."""

from __future__ import annotations

import shlex
from dataclasses import replace

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import LaunchConfig, LaunchNode
from archlog.extract.registry import Summaries, plugin_kind
from archlog.extract.summary import LoadedNodelet, NodeSummary, Port
from archlog.values import Alternatives, Concat, FullNodeName, Namespace, ParamRef, Value

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


def _manager_of(node: LaunchNode) -> str | None:
    """The full name of the manager a `nodelet load` process loads its nodelet into (None: not a loader)."""
    words = _words(node)
    return names.resolve(words[2], node.namespace, node.name) if _is_nodelet(node, "load") and len(words) >= 3 \
        else None


def _bonded_manager(node: LaunchNode) -> str | None:
    """The full name of the manager a `nodelet load` process bonds with (None: not a bonded loader)."""
    return None if "--no-bond" in _words(node) else _manager_of(node)


def in_process(node: LaunchNode, ports: list[Port]) -> list[Port]:
    """An instance's ports on its process's private namespace (handle FullNodeName("~"): a
    dynamic_reconfigure server built without a handle) under the process's name: a loaded
    nodelet's process is its manager."""
    process = _manager_of(node) or node.name
    return [replace(p, handle_ns=process) if isinstance(p.handle_ns, FullNodeName) else p for p in ports]


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


def loaded_ports(node: LaunchNode, summary: NodeSummary, summaries: Summaries,
                 diagnostics: DiagnosticSink) -> list[Port]:
    """The ports of the nodelets an instance loads into its own process, placed under their names."""
    ports: list[Port] = []
    for load in summary.loads:
        kind = plugin_kind(load.plugin)
        loaded = summaries.get(kind) if kind is not None else None
        full = _nodelet_name(load.name, node)
        if loaded is None or full is None:
            why = f"nodelet {load.plugin} has no source or model" if loaded is None else \
                f"its name is not known statically ({load.name})"
            diagnostics.add(load.file, load.line, "nodelet-unknown",
                            f"{node.name} loads a nodelet here whose ports are unknown: {why}", "warning")
            continue
        ports += [_placed(port, full, load) for port in in_process(node, loaded.ports)]
    return ports


def _nodelet_name(name: Value, node: LaunchNode) -> str | None:
    """The full name of a nodelet loaded by an instance (getName() + "_x" is the instance's name + "_x")."""
    if isinstance(name, FullNodeName):
        return names.canonical(node.name + name[1:])
    return names.resolve(name, node.namespace, node.name) if isinstance(name, str) and name else None


def _placed(port: Port, full: str, load: LoadedNodelet) -> Port:
    """A nodelet's port as the process that loads it has it: its handles made absolute (public: the
    nodelet's namespace, private: its name), a plain name resolved and remapped as the load says."""
    handle = _rebased(port.handle_ns, full)
    if not isinstance(handle, str):
        return replace(port, name=_in(port.name, full), handle_ns=handle, default=_default(port, full))
    remaps = {names.join(handle, k): names.join(handle, v) for k, v in load.remaps
              if isinstance(k, str) and isinstance(v, str) and k and v}

    def placed(name: Value) -> Value:
        if not isinstance(name, str):
            return _in(name, full)
        resolved = names.join(full, name[1:].lstrip("/")) if name.startswith("~") else names.join(handle, name)
        return remaps.get(resolved, resolved)

    absolute = isinstance(port.name, str)
    return replace(port, name=placed(port.name), handle_ns="" if absolute else handle, default=_default(port, full),
                   info_of=placed(port.info_of) if port.info_of is not None else None,
                   type_of=tuple(placed(topic) for topic in port.type_of))


def _default(port: Port, full: str) -> Value | None:
    return _in(port.default, full) if port.default is not None else None


def _rebased(handle: Value, full: str) -> Value:
    """A nodelet's handle namespace made absolute: "" is its namespace, "~..." under its name."""
    if not isinstance(handle, str):
        return _in(handle, full)
    if handle.startswith("~"):
        return names.join(full, handle[1:].lstrip("/"))
    return names.join(names.namespace_of(full), handle)


def _in(value: Value, full: str) -> Value:
    """A value whose parameters are read through the nodelet's handles."""
    if isinstance(value, ParamRef):
        return replace(value, name=_in(value.name, full), default=_in(value.default, full),
                       handle_ns=_rebased(value.handle_ns, full))
    if isinstance(value, Concat):
        return Concat(tuple(_in(p, full) for p in value.parts))
    if isinstance(value, Alternatives):
        return Alternatives(tuple(_in(o, full) for o in value.options), value.every)
    if isinstance(value, Namespace):
        return replace(value, handle=_rebased(value.handle, full))
    return value
