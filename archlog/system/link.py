"""Link one system configuration: every node instance named and placed, with the summary it runs
(extracted, modelled, plus the ports its command line and the files it names configure)."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import LaunchConfig, LaunchNode
from archlog.extract.registry import Summaries
from archlog.extract.summary import NodeSummary, Port
from archlog.extract.workspace.index import Workspace
from archlog.extract.workspace.messages import message_files
from archlog.system.camera_info import placed_camera_info
from archlog.system.configured import configured_ports
from archlog.system.controllers import controller_nodes
from archlog.system.infrastructure import infrastructure_ports
from archlog.system.instances import complete_instances
from archlog.system.named_plugins import with_plugins
from archlog.system.node_models import NodeModels, argv_ports
from archlog.system.nodelets import in_process, is_manager, loaded_ports, loader_ports, manager_summary
from archlog.system.outside import OutsidePort, outside_ports
from archlog.system.param_files import file_ports, listed
from archlog.system.plugin_slots import plugin_ports
from archlog.system.rosrun import rosrun_config
from archlog.system.transforms import configured_transforms, spawns
from archlog.values import FullNodeName, ParamList, ParamRef, Unknown


@dataclass
class Instance:
    """A node instance with its summary (None when neither source nor model was found)."""

    launch: LaunchNode
    summary: NodeSummary | None


@dataclass
class System:
    """One finished system configuration: what the facts are composed from."""

    workspace: Workspace
    config: LaunchConfig
    instances: list[Instance]
    messages: dict[str, tuple[str, Path]]  # type name -> (msg, srv or action; definition file)
    outside: list[OutsidePort] = field(default_factory=list)  # what modelled nodes it does not run would provide


def link(workspace: Workspace, config: LaunchConfig | None, models: NodeModels, extracted: Summaries,
         diagnostics: DiagnosticSink) -> System:
    """The system a configuration (None: no launch file, every executable runs once) starts, from
    the extracted summaries and the node models (the user's win over extracted ones)."""
    on_ros2 = _on_ros2(config)
    shipped = {kind: model for kind in models.builtin
               if (model := models.shipped(kind, _kind_on_ros2(kind, on_ros2, workspace))) is not None}
    summaries = {**shipped, **extracted, **models.user}
    for kind in extracted.keys() & shipped.keys() - models.user.keys():
        summaries[kind] = _source_or_model(extracted[kind], shipped[kind], diagnostics,
                                           _other_release(workspace.version(kind[0]), models.lines.get(kind, ())))
    if config is None:
        config = rosrun_config({k: v for k, v in summaries.items() if k[0] in workspace.packages},
                               workspace, diagnostics)
    complete_instances(config, summaries, diagnostics)
    config.nodes.extend(controller_nodes(config, diagnostics))
    for summary, instance, elem in models.externals:
        summaries[(summary.package, summary.executable)] = summary
        config.nodes.append(LaunchNode(elem, summary.package, summary.executable, names.join("/", instance),
                                       names.namespace_of(names.join("/", instance))))
    missing: set[tuple[str, str]] = set()
    instances = []
    for node in list(config.nodes):
        instances.append(Instance(node, _summary(node, summaries, models, config, workspace, diagnostics, missing)))
        for co_node, co_summary in _co_nodes(node, summaries.get(node.kind)):
            config.nodes.append(co_node)
            instances.append(Instance(co_node, _summary(co_node, {node.kind: co_summary}, models, config, workspace,
                                                        diagnostics, missing)))
    user = {kind: [summary] for kind, summary in models.user.items()}
    outside = outside_ports(workspace, config, {**models.builtin, **user})
    return System(workspace, config, instances, message_files(workspace), outside)


def _co_nodes(node: LaunchNode, summary: NodeSummary | None) -> list[tuple[LaunchNode, NodeSummary]]:
    """The further nodes an instance's process creates (several rclpy nodes in one program), each under
    the name its code gives it, in the instance's namespace, with the instance's remaps and parameters."""
    found = []
    for other in summary.others if summary is not None else []:
        name = other.default_name if isinstance(other.default_name, str) and other.default_name else node.type
        namespace = names.join(node.namespace, other.namespace) if isinstance(other.namespace, str) else node.namespace
        found.append((replace(node, name=names.join(namespace, name), namespace=namespace), other))
    return found


def _on_ros2(config: LaunchConfig | None) -> bool | None:
    """Whether a configuration's launch files are ROS 2 ones (None without a launch file or node)."""
    return any(node.ros2 for node in config.nodes) if config is not None and config.nodes else None


def _kind_on_ros2(kind: tuple[str, str], on_ros2: bool | None, workspace: Workspace) -> bool | None:
    """Whether an executable runs on ROS 2: as the configuration's launch files do, else as its
    package is built (ament), None when neither is known."""
    package = workspace.packages.get(kind[0])
    return on_ros2 if on_ros2 is not None else package.ament if package is not None else None


_COMPARED = ("publisher", "subscriber", "service_server", "service_client", "action_server", "action_client")


def _other_release(version: str | None, lines: tuple[str, ...]) -> str:
    """Why a model describes another release than the source's package (its version is in none of the
    release lines the model names), "" when it may be the same or it is not known."""
    if version is None or not lines or ".".join(version.split(".")[:2]) in lines:
        return ""
    return f"the model describes release line {', '.join(lines)}, the source is {version}"


def _source_or_model(source: NodeSummary, model: NodeSummary, diagnostics: DiagnosticSink,
                     other_release: str = "") -> NodeSummary:
    """A node both read from source and modelled by archlog: the source, unless it resolves fewer
    ports than the model (code in a library not read, names not known, a file that did not compile)
    and the model describes the source's release (`other_release` says why not): then the model.
    A source of another release keeps the model's names only for ports it has without a name.
    Where the two disagree on a resolved name, a model-drift note. A source that loads nodelets into
    its process is used: their ports are placed per instance (nodelets.py)."""
    if source.loads:
        return source
    ours = _resolved(source)
    theirs = _resolved(model) | {(k, _argv_label(p["name"])) for k, p, _file in model.argv_ports}
    chosen = model if len(ours) < len(theirs) and not other_release else source
    actions = {n for k, n in ours | theirs if k.startswith("action")}  # an action's topics are the action
    only_source, only_model = ([(k, n) for k, n in sorted(a - b) if not _action_topic(k, n, actions)]
                               for a, b in ((ours, theirs), (theirs, ours)))
    if only_source and only_model or chosen is source and only_model:
        shown = lambda found: ", ".join(f"{k.replace('_', ' ')} {n}" for k, n in found[:8]) or "nothing"  # noqa: E731
        where = (source.name_file, source.name_line) if source.name_file else \
            next(((p.file, p.line) for p in source.ports), (model.ports[0].file, model.ports[0].line) if model.ports
                 else (source.package, 1))
        diagnostics.add(where[0], where[1] or 1, "model-drift",
                        f"{source.package}/{source.executable}: the source ({len(ours)} resolved ports) has "
                        f"{shown(only_source)} that archlog's model ({len(theirs)}) lacks, the model "
                        f"{shown(only_model)}; the {'model' if chosen is model else 'source'} is used"
                        f"{f' ({other_release})' if other_release else ''}", "note")
    return replace(source, ports=source.ports + _named_by_model(source, model)) if other_release else chosen


def _named_by_model(source: NodeSummary, model: NodeSummary) -> list[Port]:
    """The model's ports that name what the source leaves unnamed: of a kind and type the source
    has a port of whose name it does not know (an action server a plugin creates under a name
    from a parameter), and that the source does not have by name."""
    unnamed = [p for p in source.ports if p.kind in _COMPARED and _port_key(p) is None]
    named = _resolved(source)
    return [p for p in model.ports if (key := _port_key(p)) is not None and key not in named and
            any(u.kind == p.kind and (u.type == p.type or isinstance(u.type, Unknown)) for u in unnamed)]


def _argv_label(raw: object) -> str:
    """A model port named from the command line, as a model-drift note shows it."""
    if isinstance(raw, dict) and raw.keys() & {"argv", "argv_from"}:
        return f"<argument {raw['argv']}>" if "argv" in raw else f"<arguments from {raw['argv_from']}>"
    return str(raw.get("default", raw)) if isinstance(raw, dict) else str(raw)


def _action_topic(kind: str, name: str, actions: set[str]) -> bool:
    ns, _, last = name.rpartition("/")
    return kind in ("publisher", "subscriber") and ns in actions and last in ("goal", "cancel", "status", "feedback",
                                                                           "result")


def _resolved(summary: NodeSummary) -> set[tuple[str, str]]:
    """(kind, name) of the ports whose names are known (a parameter's default counts, and so does
    a list parameter's or a parameter's file's ports, as one), relative names and global ones alike
    without their leading slash."""
    return {key for port in summary.ports if (key := _port_key(port)) is not None}


def _port_key(port: Port) -> tuple[str, str] | None:
    """(kind, name) of a port whose name is known, as `_resolved` compares them; None otherwise."""
    if isinstance(port.name, ParamList):
        return port.kind, f"{{{port.name.name}: {port.name.entry or port.name.field}}}"
    name = port.name.default if isinstance(port.name, ParamRef) else port.name
    handle = port.handle_ns
    if port.kind in _COMPARED and isinstance(name, str) and isinstance(handle, str):
        full = name if name.startswith(("/", "~")) or not handle else \
            (f"~{name}" if handle == "~" else f"{handle.rstrip('/')}/{name}")
        if full.strip("/"):
            return port.kind, full.lstrip("/")
    return None


def _summary(node: LaunchNode, summaries: Summaries, models: NodeModels, config: LaunchConfig,
             workspace: Workspace, diagnostics: DiagnosticSink, missing: set[tuple[str, str]]) -> NodeSummary | None:
    """What one instance runs, with its configured ports and those of the plugins its parameters
    choose (the slots of its model, also when its source is read), and its transforms; a kind with
    neither source nor model is reported once.
    A nodelet manager runs the nodelet mechanism, whatever the source of `nodelet` says."""
    summary = manager_summary(node, config) if is_manager(node) else summaries.get(node.kind)
    if summary is not None and summary.loads:
        summary = replace(summary, ports=summary.ports + loaded_ports(node, summary, summaries, diagnostics))
    if summary is not None and summary.plugin_loads:
        summary = with_plugins(node, summary, summaries, workspace, diagnostics)
    model = models.user.get(node.kind) or models.shipped(node.kind, node.ros2)
    if summary is not None and summary.argv_ports:  # the model is used
        summary = replace(summary, ports=summary.ports + argv_ports(summary, node.args)[0])
    elif summary is not None and model is not None and model.argv_ports:
        summary = replace(summary, ports=_without(summary.ports, *argv_ports(model, node.args)))
    if summary is not None and any(isinstance(p.handle_ns, FullNodeName) for p in summary.ports):
        summary = replace(summary, ports=in_process(node, summary.ports))
    if summary is not None and any(p.info_of is not None for p in summary.ports):
        summary = replace(summary, ports=[placed_camera_info(p, node) for p in summary.ports])
    slots = summary.plugins if summary is not None and summary.plugins else model.plugins if model else ()
    if slots and summary is not None and summary.plugin_loads:  # the slots say what its plugins create
        summary = replace(summary, plugin_loads=[])
    configured, unread = configured_ports(node, config, workspace, diagnostics)
    extra = configured + loader_ports(node) + plugin_ports(node, slots, models.classes, config, diagnostics)
    if extra:
        summary = replace(summary, ports=summary.ports + extra) if summary is not None else \
            NodeSummary(node.pkg, node.type, "model", ports=extra, incomplete="only its configured ports are known")
    if summary is not None and unread and not summary.incomplete:
        summary = replace(summary, incomplete=unread)
    if summary is not None and any(listed(p) for p in summary.ports):
        summary = replace(summary, ports=file_ports(node, summary.ports, config, workspace, diagnostics))
    if summary is not None:
        summary = _with_transforms(_with_marks(summary, model), model, node, config, workspace, diagnostics)
        summary = replace(summary, ports=summary.ports + infrastructure_ports(node, summary, workspace))
    if summary is None and node.kind not in missing:
        kind = node.kind
        missing.add(kind)
        diagnostics.add(node.elem.file, node.elem.line, "no-model",
                        f"no source or model for {'/'.join(kind)}: the ports of {node.name} are unknown; "
                        f"describe it in a YAML file passed with --model, starting from {{package: {kind[0]}, "
                        f"executable: {kind[1]}, publishers: [{{name: TOPIC, type: PKG/TYPE}}], "
                        "subscribers: [], services: [], params: [{name: ~PARAM, default: VALUE}]}", "warning")
    return summary


def _without(ports: list[Port], present: list[Port], absent: list[Port]) -> list[Port]:
    """A source's ports less those its model creates only under a command-line condition this instance
    does not meet (options the source parses from argv, which extraction does not follow)."""
    dropped = {_port_key(p) for p in absent} - {_port_key(p) for p in present} - {None}
    return [port for port in ports if _port_key(port) not in dropped]
def _with_marks(summary: NodeSummary, model: NodeSummary | None) -> NodeSummary:
    """A node read from source that archlog models: each source port gets the `after_tf` and `optional`
    marks of the model's port of that kind and name (extraction recovers neither)."""
    if model is None or summary.origin == "model":
        return summary
    marks: dict[tuple[str, str] | None, Port] = \
        {key: port for port in model.ports if (port.after_tf or port.optional) and (key := _port_key(port))}
    if not marks:
        return summary
    return replace(summary, ports=[replace(port, after_tf=mark.after_tf or port.after_tf,
                                           optional=mark.optional or port.optional)
                                   if (mark := marks.get(_port_key(port))) else port for port in summary.ports])


def _with_transforms(summary: NodeSummary, model: NodeSummary | None, node: LaunchNode, config: LaunchConfig,
                     workspace: Workspace, diagnostics: DiagnosticSink) -> NodeSummary:
    """The summary with its model's tf keys (also when its source is read: extraction does not recover
    transforms) and the transforms its robot description, command line or spawned gazebo plugins give."""
    if model is not None and not summary.tf_declared and not summary.tf_waits:
        summary = replace(summary, transforms=model.transforms, tf_waits=model.tf_waits,
                          tf_declared=model.tf_declared, tf_description=model.tf_description, tf_args=model.tf_args)
    if not (summary.tf_description or summary.tf_args or spawns(node)):
        return summary
    configured = configured_transforms(node, summary, config, workspace, diagnostics)
    if configured is None:  # not known statically: it may broadcast any transform
        return replace(summary, tf_declared=False, tf_unknown=True)
    return replace(summary, transforms=summary.transforms + tuple(configured), tf_declared=True)
