"""The live ROS 2 graph, read by an rclpy node on one DDS domain: every node, its publishers,
subscribers, services, clients, action servers and action clients with their types, and each topic
endpoint's QoS as DDS reports it.

rclpy is optional (the `ros2` extra): it is imported when a graph is read, and its absence is a
`Ros2Unavailable` error, never an import error of this module.

The ports every rclpy/rclcpp node creates on its own (/rosout, /parameter_events, the parameter,
type-description and logger services, /clock) are kept apart in `Ros2Graph.infrastructure`.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

from archlog.observe import ROS2_QOS_DEFAULTS, Architecture

OBSERVER = "archlog_observer"
PORT_KINDS = ("publishers", "subscribers", "services", "clients", "action_servers", "action_clients")
INFRA_TOPICS = frozenset({"/rosout", "/parameter_events", "/clock"})
INFRA_SERVICES = ("describe_parameters", "get_parameter_types", "get_parameters", "list_parameters",
                  "set_parameters", "set_parameters_atomically", "get_type_description",
                  "get_logger_levels", "set_logger_levels")
ACTION_PART = "/_action/"  # an action's own topics and services live under NAME/_action/
# QoS policies compared with the recovered ones (history and depth of a remote endpoint are not
# sent by DDS discovery); a policy at the value ROS 2 gives by default is left out on both sides
QOS_DURATIONS = ("deadline", "lifespan", "liveliness_lease_duration")
EMPTY_WAIT = 5.0  # seconds without any node before a domain is taken to be empty
INFINITE_US = 2**31  # durations at or above this (DDS's infinite is 2^31 - 1 s) are infinite


class Ros2Unavailable(RuntimeError):
    """rclpy (and an RMW implementation) cannot be imported or initialised here."""


Port = tuple[str, str, str, str]  # (kind, node, name, type)


@dataclass(frozen=True)
class Ros2Graph:
    """A snapshot of a domain. `ports` and `infrastructure` are (kind, node, name, type) rows,
    `qos` (node, topic, "publisher" | "subscriber", policy, value) rows of non-default policies."""

    nodes: frozenset[str]
    ports: frozenset[Port]
    infrastructure: frozenset[Port] = frozenset()
    qos: frozenset[tuple[str, str, str, str, str]] = frozenset()

    def architecture(self) -> Architecture:
        """The graph in the shape `archlog diff` compares (services, clients and actions without types)."""
        def rows(kind: str, typed: bool) -> frozenset:
            return frozenset((n, name, t) if typed else (n, name) for k, n, name, t in self.ports if k == kind)

        return Architecture(self.nodes, rows("publishers", True), rows("subscribers", True), rows("services", False),
                            clients=rows("clients", False), action_servers=rows("action_servers", False),
                            action_clients=rows("action_clients", False), qos=self.qos,
                            kinds=Architecture.ROS2_KINDS)


def is_infrastructure(kind: str, node: str, name: str) -> bool:
    """A port every node has, whatever its code: the logging and parameter topics, the parameter,
    type-description and logger services, the sim-time clock."""
    if kind in ("publishers", "subscribers"):
        return name in INFRA_TOPICS
    return kind == "services" and name in {f"{node.rstrip('/')}/{s}" for s in INFRA_SERVICES}


def read_graph(domain: int | None = None, settle: float = 2.0, expect: frozenset[str] = frozenset(),
               timeout: float = 20.0) -> Ros2Graph:
    """The graph of `domain` (None: ROS_DOMAIN_ID's), once discovery has settled: the nodes in
    `expect` are all present and nothing changed for `settle` seconds, or `timeout` has passed."""
    rclpy, action_graph = _rclpy()
    context = rclpy.context.Context()
    try:
        rclpy.init(context=context, domain_id=domain)
    except Exception as exc:  # rclpy raises RCLError and friends, which have no common base here
        raise Ros2Unavailable(f"rclpy cannot start on domain {domain}: {exc}") from None
    try:
        node = rclpy.create_node(OBSERVER, context=context, start_parameter_services=False, enable_rosout=False)
        try:
            return _settled(node, action_graph, settle, expect, timeout)
        finally:
            node.destroy_node()
    finally:
        context.try_shutdown()


def _rclpy() -> tuple[Any, Any]:
    try:
        import rclpy
        from rclpy.action import graph
        return rclpy, graph
    except ImportError as exc:  # a missing wheel, or a native library that does not load
        raise Ros2Unavailable(f"rclpy is not importable ({exc}); install archlog's ros2 extra: "
                              "pip install 'archlog[ros2]'") from None


def _settled(node: Any, action_graph: Any, settle: float, expect: frozenset[str], timeout: float) -> Ros2Graph:
    """Discovery of the other participants takes a while (longer on a busy machine): an empty graph
    counts as settled only after EMPTY_WAIT seconds."""
    start = time.monotonic()
    end = start + timeout
    last, since = None, start
    while True:
        graph = _snapshot(node, action_graph)
        now = time.monotonic()
        if graph != last:
            last, since = graph, now
        waited = bool(graph.nodes) or now - start >= EMPTY_WAIT
        if expect <= graph.nodes and waited and now - since >= settle or now >= end:
            return graph
        time.sleep(0.2)


def _snapshot(node: Any, action_graph: Any) -> Ros2Graph:
    readers = {
        "publishers": node.get_publisher_names_and_types_by_node,
        "subscribers": node.get_subscriber_names_and_types_by_node,
        "services": node.get_service_names_and_types_by_node,
        "clients": node.get_client_names_and_types_by_node,
        "action_servers": lambda n, ns: action_graph.get_action_server_names_and_types_by_node(node, n, ns),
        "action_clients": lambda n, ns: action_graph.get_action_client_names_and_types_by_node(node, n, ns),
    }
    names: set[str] = set()
    ports: set[Port] = set()
    for base, namespace in node.get_node_names_and_namespaces():
        full = namespace.rstrip("/") + "/" + base
        if full == "/" + OBSERVER:
            continue
        names.add(full)
        for kind, read in readers.items():
            try:
                found = read(base, namespace)
            except Exception:  # the node left between listing and reading (rclpy raises NodeNameNonExistentError)
                continue
            ports |= {(kind, full, name, type_) for name, types in found if ACTION_PART not in name for type_ in types}
    own = frozenset(p for p in ports if not is_infrastructure(*p[:3]))
    qos = frozenset(row for kind, n, topic, _t in own if kind in ("publishers", "subscribers")
                    for row in _endpoint_qos(node, kind, n, topic))
    return Ros2Graph(frozenset(names), own, frozenset(ports) - own, qos)


def _endpoint_qos(node: Any, kind: str, full: str, topic: str) -> list[tuple[str, str, str, str, str]]:
    """The non-default QoS policies of `full`'s endpoints on `topic`."""
    read = node.get_publishers_info_by_topic if kind == "publishers" else node.get_subscriptions_info_by_topic
    direction = kind[:-1]
    rows = []
    for info in read(topic):
        if info.node_namespace.rstrip("/") + "/" + info.node_name != full:
            continue
        rows += [(full, topic, direction, policy, value) for policy, value in qos_policies(info.qos_profile, direction)]
    return rows


def qos_policies(profile: Any, direction: str) -> list[tuple[str, str]]:
    """(policy, value) of an rclpy QoSProfile that differ from ROS 2's defaults, named as archlog's
    `qos` and `qos_duration` facts name them (durations in microseconds)."""
    found = []
    for policy, default in ROS2_QOS_DEFAULTS.items():
        value = getattr(profile, policy).name.lower()
        if value not in (default, "system_default", "unknown"):
            found.append((policy, value))
    for policy in QOS_DURATIONS:
        if policy == "lifespan" and direction == "subscriber":
            continue  # a reader has no lifespan
        micros = getattr(profile, policy).nanoseconds // 1000
        if 0 < micros < INFINITE_US:
            found.append((policy, str(micros)))
    return found

