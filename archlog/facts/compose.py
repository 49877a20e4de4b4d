"""Translate a linked system into facts: resolve every port's name in its instance's context."""

from __future__ import annotations

import math
from dataclasses import replace

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import LaunchConfig, LaunchNode
from archlog.extract.summary import NodeSummary, Port, Site
from archlog.facts.behavior import Sites, add_behavior
from archlog.facts.followed_types import Following, add_followed
from archlog.facts.namespaces import add_namespaces
from archlog.facts.parameters import add_param_spec, add_parameters
from archlog.facts.store import FactStore
from archlog.system.command_line import command_word
from archlog.system.link import System
from archlog.system.node_models import UNSET
from archlog.values import (
    Alternatives,
    CommandArg,
    Concat,
    Namespace,
    OverBudget,
    ParamList,
    ParamRef,
    Switch,
    Unknown,
    Value,
    concat,
    one_of,
    partly_known,
)

QOS_DURATIONS = ("deadline", "lifespan", "liveliness_lease_duration")
_MAX_INT = 2**31 - 1  # clingo's integers are 32-bit
NAMED_PORTS = ("publisher", "subscriber", "service_server", "service_client", "action_server", "action_client")


def compose(system: System, diagnostics: DiagnosticSink) -> FactStore:
    """Build the fact store of one linked system configuration (near-miss names are added by
    `near_misses.add_near_names`, once the ports are known)."""
    store = FactStore()
    workspace, config = system.workspace, system.config
    following: list[Following] = []
    for package in workspace.packages.values():
        store.add("package", package.name, workspace.display(package.path))
        for exe in package.executables.values():
            store.add("executable", package.name, exe.name, exe.lang,
                      workspace.display(exe.sources[0]) if exe.sources else "")
    for type_name, (kind, path) in sorted(system.messages.items()):
        store.add("message_type", type_name, kind, workspace.display(str(path)))
    for elem, src, dst in config.scope_remaps:
        store.add("remap_declared", elem.id, src, dst)
        store.locate(elem.id, elem.file, elem.line)
    for name, (value, elem) in config.params.items():
        store.add("param", name, value if isinstance(value, Unknown) else _text(value), elem.id)
        store.locate(elem.id, elem.file, elem.line)
    for node, summary in ((i.launch, i.summary) for i in system.instances):
        store.add("node", node.name, node.pkg, node.type, node.elem.id)
        store.locate(node.elem.id, node.elem.file, node.elem.line)
        if node.condition:
            store.add("conditional", node.elem.id, node.condition)
        if node.condition and node.when is not None:
            store.add("condition_settled", node.elem.id)
            for arg, values in sorted(node.when.items()):
                store.add("condition_on", node.elem.id, arg)
                for value in sorted(values):
                    store.add("condition_value", node.elem.id, arg, value)
        if node.ros2:
            store.add("ros2_node", node.name)
        if node.standalone:
            store.add("standalone", node.elem.id)
        if node.name_unknown:
            store.add("node_name_unknown", node.elem.id)
        for depth, include in enumerate(node.chain, 1):
            store.add("included_through", node.elem.id, include.id, depth)
            store.locate(include.id, include.file, include.line)
        if node.plugin:
            store.add("nodelet", node.name, node.plugin, node.manager or "")
        for src, dst, elem in node.remaps:  # an opaque node's too: they tell which names it may use
            store.add("remap", elem.id, node.name, names.resolve(src, node.namespace, node.name),
                      names.resolve(dst, node.namespace, node.name))
            store.locate(elem.id, elem.file, elem.line)
        if summary is None:
            continue
        store.add("node_source", node.name, summary.origin)
        if summary.incomplete:
            store.add("node_incomplete", node.name, summary.incomplete)
        for index, (file, line) in enumerate(summary.plugin_loads, 1):
            hole = f"{node.elem.id}.plugins{index}"
            store.add("plugin_hole", hole, node.name, f"the pluginlib classes {node.name} creates here (not read)")
            store.locate(hole, file, line)
        _instance(store, node, summary, config, following)
    for index, (file, line, why) in enumerate(config.holes, 1):
        store.add("launch_hole", f"h{index}", why)
        store.locate(f"h{index}", file, line)
    for port in system.outside:
        store.add("outside_port", port.kind, port.name, port.type, port.provider)
    add_followed(store, following)
    _param_topics(store, system)
    add_parameters(store, system)
    _private_names(store)
    _unknown_port_names(store, diagnostics)
    _unknown_patterns(store)
    add_namespaces(store)
    return store


def _unknown_port_names(store: FactStore, diagnostics: DiagnosticSink) -> None:
    """A note at each call that creates a port whose name is unknown, naming what is unknown."""
    for rel in NAMED_PORTS:
        for port, _node, name, *_rest in store.rows(rel):
            if isinstance(name, Unknown):
                file, line, column = store.location(str(port)) or (name.file, name.line, 0)
                what = rel.replace("_", " ")
                if isinstance(name, OverBudget):
                    diagnostics.add(file, line, "budget-exceeded", f"the name of this {what} would be one of "
                                    f"{name.expr}; it is not read", "warning", column=column)
                    continue
                known = " and ".join(part for part in (name.prefix and f"starts with {name.prefix}",
                                                       name.suffix and f"ends with {name.suffix}") if part)
                consequence = f"it may connect to any name that {known}" if known else "its connections are not checked"
                diagnostics.add(file, line, "port-name-unknown",
                                f"the name of this {what} is unknown: {name.expr}; {consequence}", column=column)


def _unknown_patterns(store: FactStore) -> None:
    """unknown_pattern facts: the known start and end of the unknown names ports use."""
    for rel in (*NAMED_PORTS, "port_source_name"):
        for row in store.rows(rel):
            name = row[1] if rel == "port_source_name" else row[2]
            if isinstance(name, Unknown) and (name.prefix or name.suffix):
                store.add("unknown_pattern", name, name.prefix, name.suffix)


def _instance(store: FactStore, node: LaunchNode, summary: NodeSummary, config: LaunchConfig,
              following: list[Following]) -> None:
    """The facts of one instance's ports and behavior; ports whose type follows other topics' go to
    `following`, to be typed once every instance's publishers are known."""
    pairs = [(src, dst) for src, dst, _ in node.remaps]
    remaps = names.resolve_remaps(pairs[::-1] if node.ros2 else pairs, node.namespace, node.name)
    ports = [e for p in summary.ports if _present(p, node, config) for e in _each(p, node, config)]
    waits = _transforms(store, node, summary, config, remaps)
    sites: Sites = {}
    for port in [q for p in ports for q in [p, *action_topics(p)]]:
        pid = store.new_id("p")
        store.locate(pid, port.file, port.line, port.column)
        for wait in port.after_tf:
            if wait in waits:  # an id naming no wait is a model-schema error
                store.add("port_after_tf", pid, waits[wait])
        if port.optional:
            store.add("optional_port", pid)
        if port.infrastructure:
            store.add("infrastructure_port", pid, port.infrastructure)
        if port.param is not None:
            add_param_spec(store, pid, port.param)
        sites.setdefault(Site(port.file, port.line), []).append((port.kind, pid))
        for policy, value in port.qos:
            store.add("qos", pid, policy, value)
            if policy in QOS_DURATIONS and (micros := _microseconds(value)) is not None:
                store.add("qos_duration", pid, policy, micros)
        if port.queue is not None:
            store.add("queue_size", pid, _single(_bind(port.queue, node, config)))
        if port.kind == "timer":
            for period in _options(_bind(port.name, node, config)):
                store.add("timer", pid, node.name, period)
            continue
        handle_ns = _PRIVATE if port.kind in ("param_read", "param_write") and _own_param(port.handle_ns, node) \
            else port.handle_ns
        before_remaps = [_resolve(option, handle_ns, node, config, remaps)
                         for option in _options(_bind(port.name, node, config))]
        resolved = [(b, _remapped(b, remaps)) for b in before_remaps]
        if isinstance(port.name, ParamRef) and isinstance(key := _param_key(port.name, node, config), str):
            store.add("port_name_param", pid, key)
        if not node.ros2 and isinstance(handle := _handle_namespace(port.handle_ns, node, config), str) and handle:
            store.add("handle_namespace", pid, handle)
        if len(resolved) > 1:
            store.add("alternative_names", pid, len(resolved))
        last = _bind(port.default, node, config) if port.default is not None else \
            Unknown("no default" if port.kind == "param_read" else "value", port.file, port.line)
        inputs = tuple(_remapped(_resolve(option, port.handle_ns, node, config, remaps), remaps)
                       for topic in port.type_of for option in _options(_bind(topic, node, config)))
        for before, after in resolved:
            if port.kind in ("param_read", "param_write"):
                store.add(port.kind, pid, node.name, after, _single(last))
            elif port.type_of and isinstance(port.type, Unknown):
                following.append(Following(pid, port.kind, node.name, after, inputs, port.type))
            else:
                store.add(port.kind, pid, node.name, after, _type_name(_single(_bind(port.type, node, config))))
            store.add("port_source_name", pid, before)
    add_behavior(store, node.name, summary, sites, lambda value: _single(_bind(value, node, config)))


def _transforms(store: FactStore, node: LaunchNode, summary: NodeSummary, config: LaunchConfig,
                remaps: dict[str, str]) -> dict[str, str]:
    """tf facts of one instance: the transforms it broadcasts (frames bound to its parameters, the
    topics that start a broadcast resolved as its ports' names are) and those it waits for; returns
    the fact id of each wait by its model id."""
    if summary.tf_declared:
        store.add("tf_declared", node.name)
    if summary.tf_unknown:
        store.add("tf_unknown", node.name)
    for transform in summary.transforms:
        if not _holds(transform.condition, node, config):
            continue
        after = [_resolve(option, "", node, config, remaps) for value in transform.after
                 for option in _options(_bind(value, node, config)) if option != ""]
        if transform.after and not after:
            continue  # started only by inputs the configuration does not give it
        tid = store.new_id("t")
        store.locate(tid, transform.file, transform.line)
        store.add("tf_broadcast", tid, node.name, _frame(transform.parent, node, config),
                  _frame(transform.child, node, config))
        if all(isinstance(topic, str) for topic in after):  # an unknown one might be anything: no condition
            for topic in after:
                store.add("tf_broadcast_after", tid, names.remap(str(topic), remaps))
    waits = {wait.id: store.new_id("t") for wait in summary.tf_waits}
    for wait in summary.tf_waits:
        store.locate(waits[wait.id], wait.file, wait.line)
        store.add("tf_wait", waits[wait.id], node.name, _frame(wait.target, node, config),
                  _frame(wait.source, node, config))
        for before in wait.after_tf:
            if before in waits:
                store.add("tf_wait_after", waits[wait.id], waits[before])
    return waits


def _frame(value: Value, node: LaunchNode, config: LaunchConfig) -> str | Unknown:
    """A frame id bound for the instance, without the leading slash tf2 ignores."""
    frame = _single(_bind(value, node, config))
    return frame.lstrip("/") if isinstance(frame, str) else frame


# actionlib (ROS 1): the topics under an action's namespace, as seen from the server
_ACTION_TOPICS = (("goal", "subscriber", "ActionGoal"), ("cancel", "subscriber", "actionlib_msgs/GoalID"),
                  ("status", "publisher", "actionlib_msgs/GoalStatusArray"),
                  ("feedback", "publisher", "ActionFeedback"), ("result", "publisher", "ActionResult"))
_FLIP = {"subscriber": "publisher", "publisher": "subscriber"}


def action_topics(port: Port) -> list[Port]:
    """The five topics of a ROS 1 action server or client (ROS 2 actions are not topics)."""
    if port.kind not in ("action_server", "action_client") or \
            (isinstance(port.type, str) and "/action/" in port.type):
        return []
    topics = []
    for suffix, kind, message in _ACTION_TOPICS:
        if "/" in message:
            type_: Value = message
        else:
            type_ = port.type + message if isinstance(port.type, str) else port.type
        kind = kind if port.kind == "action_server" else _FLIP[kind]
        topics.append(replace(port, kind=kind, name=concat(port.name, "/" + suffix), type=type_))
    return topics


def _resolve(name: str | Unknown, handle_ns: Value, node: LaunchNode, config: LaunchConfig,
             remaps: dict[str, str]) -> str | Unknown:
    """Resolve one bound port name in the instance's context (handle namespace, `~`), before the name's
    own remap. As roscpp does, a ROS 1 NodeHandle's namespace is itself remapped with `remaps` first."""
    if isinstance(name, Unknown):
        return _known_parts(name, handle_ns, node, config, remaps)
    if name.startswith("~"):
        return names.join(node.name, name[1:].lstrip("/"))
    if name.startswith("/"):
        return names.canonical(name)
    handle = _handle_namespace(handle_ns, node, config)
    if isinstance(handle, Unknown):  # it keeps the known start of the handle's namespace
        start = _known_parts(handle, "", node, config, remaps).prefix
        return Unknown(f"{handle.expr}/{name}", handle.file, handle.line, start, _tail("/" + name))
    return names.join(names.remap(handle, remaps) if handle and not node.ros2 else handle or node.namespace, name)


def _known_parts(name: Unknown, handle_ns: Value, node: LaunchNode, config: LaunchConfig,
                 remaps: dict[str, str]) -> Unknown:
    """An unknown name's known start resolved as the name would be (in the handle's namespace, `~` in the
    node's), and its known end cleaned."""
    prefix = _resolve(name.prefix, handle_ns, node, config, remaps) if name.prefix else ""
    return replace(name, prefix="" if isinstance(prefix, Unknown) else prefix.rstrip("/"), suffix=_tail(name.suffix))


def _tail(text: str) -> str:
    """A known end of a name as the name resolves: slashes collapsed, none trailing ("" for only slashes)."""
    return names.canonical(text) if text.strip("/") else ""


def _remapped(name: str | Unknown, remaps: dict[str, str]) -> str | Unknown:
    """A resolved name after the instance's remaps; an unknown one a remap might match could become anything."""
    if isinstance(name, str):
        return names.remap(name, remaps)
    return name.vague() if any(name.fits(source) for source in remaps) else name


def _handle_namespace(handle_ns: Value, node: LaunchNode, config: LaunchConfig) -> str | Unknown:
    """The resolved namespace of the handle a port was created on, before remapping ('' for the node's own)."""
    handle = _single(_bind(handle_ns, node, config))
    return names.resolve(handle, node.namespace, node.name) if isinstance(handle, str) and handle else handle


def _private_names(store: FactStore) -> None:
    """private_name facts: the names ports use that lie in a node instance's private namespace."""
    nodes = {str(row[0]) for row in store.rows("node")}
    depth = max((node.count("/") for node in nodes), default=0)  # a node name is at most this many segments deep
    used = {row[2] for rel in NAMED_PORTS for row in store.rows(rel) if isinstance(row[2], str) and row[2].startswith("/")}
    for name in sorted(used):
        # the name's namespaces no deeper than a node name, deepest first (linear in the name's length)
        segments = names.canonical(name).split("/")[1:-1][:depth]
        parents = ["/" + "/".join(segments[:k]) for k in range(len(segments), 0, -1)]
        for parent in parents:
            if parent in nodes:
                store.add("private_name", name, parent)


def _param_topics(store: FactStore, system: System) -> None:
    """param_topic facts: a parameter the configuration sets in a node's private namespace, named like
    a topic parameter (its last segment ends in `topic`, or some port takes its name from a parameter
    of that last segment), whose value is a graph name: that name resolved as the node would."""
    topic_params = {str(key).rsplit("/", 1)[-1] for _port, key in store.rows("port_name_param")}
    nodes: dict[str, list[LaunchNode]] = {}
    for instance in system.instances:  # a name given twice is reported elsewhere; both instances count here
        nodes.setdefault(instance.launch.name, []).append(instance.launch)
    for name, (value, _elem) in system.config.params.items():
        owner, _, last = name.rpartition("/")
        if isinstance(value, str) and names.is_valid(value) and value != "/" and \
                (last.endswith("topic") or last in topic_params):
            for node in nodes.get(owner, ()):
                store.add("param_topic", name, node.name, names.resolve(value, node.namespace, node.name))


def _param_key(ref: ParamRef, node: LaunchNode, config: LaunchConfig) -> str | Unknown:
    """The resolved name of the parameter a value is read from."""
    handle_ns = _PRIVATE if _own_param(ref.handle_ns, node) else ref.handle_ns
    return _resolve(_single(_bind(ref.name, node, config)), handle_ns, node, config, {})


_PRIVATE = "~"


def _own_param(handle_ns: Value, node: LaunchNode) -> bool:
    """A ROS 2 parameter named without a handle (as a model writes `tf_broadcast`): every ROS 2
    parameter is a node's own, so the name is relative to the node, not to its namespace."""
    return node.ros2 and handle_ns == ""


def _bind(value: Value, node: LaunchNode, config: LaunchConfig) -> str | Unknown | Alternatives:
    """Evaluate a recovered value for one instance: parameters come from the configuration."""
    if isinstance(value, (str, Unknown)):
        return value
    if isinstance(value, ParamRef):
        key = _param_key(value, node, config)
        if isinstance(key, str) and key in config.params:
            found = config.params[key][0]
            return found if isinstance(found, Unknown) else _text(found)
        return _bind(value.default, node, config)
    if isinstance(value, Namespace):
        return _namespace(value, node, config)
    if isinstance(value, CommandArg):
        given = command_word(value, node.args)
        return given if given is not None else _bind(value.default, node, config)
    if isinstance(value, Switch):
        subject = _single(_bind(value.subject, node, config))
        if isinstance(subject, Unknown):
            return subject
        return _bind(value.when_equal if subject == value.equals else value.otherwise, node, config)
    if isinstance(value, Alternatives):
        bound = [_bind(option, node, config) for option in value.options]
        flat = [o for b in bound for o in _options(b)]
        distinct = list(dict.fromkeys(flat))
        if len(distinct) == 1:
            return distinct[0]
        if over := next((o for o in distinct if isinstance(o, OverBudget)), None):
            return over
        if any(isinstance(o, Unknown) for o in distinct):
            return one_of(distinct)  # what every option is known to start and end with, no more
        return Alternatives(tuple(distinct), value.every)
    assert isinstance(value, Concat), value  # a list-parameter name is expanded (_each) before binding
    joined = concat(*[_bind(p, node, config) for p in value.parts])
    if isinstance(joined, Concat):
        return partly_known(joined.parts)  # type: ignore[arg-type]  # bound parts are strings and unknowns
    assert isinstance(joined, (str, Unknown, Alternatives))  # concat of bound parts has no reference left
    return joined


def _namespace(value: Namespace, node: LaunchNode, config: LaunchConfig) -> str | Unknown:
    """The namespace a handle's getNamespace() returns in this instance, as roscpp resolves it (the handle's
    own namespace remapped), less the characters the code cut off."""
    handle = _handle_namespace(value.handle, node, config)
    if isinstance(handle, Unknown):
        return handle
    remaps = names.resolve_remaps([(src, dst) for src, dst, _ in node.remaps], node.namespace, node.name)
    return (names.remap(handle, remaps) if handle else names.canonical(node.namespace) or "/")[value.cut:]


def _each(port: Port, node: LaunchNode, config: LaunchConfig) -> list[Port]:
    """A port named from a list parameter (alone, or joined with other parts: a Python loop's
    `topic + "/image"`) becomes one port per element of that list."""
    parts = port.name.parts if isinstance(port.name, Concat) else (port.name,)
    listed = next((part for part in parts if isinstance(part, ParamList)), None)
    if listed is None:
        return [port]
    key = _resolve(listed.name, port.handle_ns, node, config, {})
    items = config.params.get(key, (None,))[0] if isinstance(key, str) else None
    if items is None and listed.defaults is not None:
        items = list(listed.defaults)
    if not isinstance(items, list):
        why = "not set by the configuration" if items is None else f"set to {_text(items)}, not a list"
        items = [Unknown(f"each element of {listed.name} ({why})", listed.file, listed.line)]
    names = [item.get(listed.field) if isinstance(item, dict) and listed.field else item for item in items]
    elements = [name if isinstance(name, Unknown) else str(name) for name in names if name is not None]
    return [replace(port, name=concat(*[element if part is listed else part for part in parts])) for element in elements]


def _present(port: Port, node: LaunchNode, config: LaunchConfig) -> bool:
    """A port with conditions exists when each condition's value (bound for this instance) matches;
    an unknown value keeps the port."""
    return all(_holds(condition, node, config) for condition in (port.condition, *port.also))


def _holds(condition: tuple[Value, str | None] | None, node: LaunchNode, config: LaunchConfig) -> bool:
    """A model's condition bound for the instance: no condition, a match, or an unknown value."""
    if condition is None:
        return True
    value = _single(_bind(condition[0], node, config))
    if condition[1] is None:  # `set: true`
        return value != UNSET
    return isinstance(value, Unknown) or value.lower() == condition[1].lower()


def _type_name(type_: str | Unknown) -> str | Unknown:
    """One spelling per type: a C++ spelling (`std_msgs::msg::String`) becomes `std_msgs/msg/String`."""
    return type_.replace("::", "/") if isinstance(type_, str) else type_


def _microseconds(seconds: str) -> int | None:
    """A QoS duration in whole microseconds (clamped to clingo's range), or None when not a number."""
    try:
        value = float(seconds)
    except ValueError:
        return None
    return min(round(value * 1_000_000), _MAX_INT) if math.isfinite(value) and value >= 0 else None


def _options(value: str | Unknown | Alternatives) -> list[str | Unknown]:
    return list(value.options) if isinstance(value, Alternatives) else [value]  # type: ignore[arg-type]


def _single(value: str | Unknown | Alternatives) -> str | Unknown:
    """A value that must be one thing (a type, a default, a handle): alternatives are unknown."""
    if isinstance(value, Alternatives):
        return Unknown("one of " + ", ".join(map(str, value.options)), "", 0)
    return value


def _text(value: object) -> str:
    if isinstance(value, bool):
        return str(value).lower()
    return str(value)
