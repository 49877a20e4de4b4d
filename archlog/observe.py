"""The observed architecture: read a running ROS 1 master (or saved `ros2 node info` output),
compare it with the recovered one.

Both sides have one shape, `Architecture`: nodes, publishers and subscribers (node, topic, type),
and services (node, service). The master keeps one type per topic (the first registration), so
subscribers are compared by node and topic only. Infrastructure (/rosout, logger services) is left
out.
"""

from __future__ import annotations

import json
import xmlrpc.client
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, ClassVar

import yaml

from archlog.facts.store import FactStore
from archlog.values import Unknown

CALLER_ID = "/archlog_observer"
INFRA_NODES = frozenset({"/rosout"})
INFRA_TOPICS = frozenset({"/rosout", "/rosout_agg", "/clock"})
LOGGER_SERVICES = ("get_loggers", "set_logger_level")
KINDS = ("nodes", "publishers", "subscribers", "services")
ROS2_INFRA_TOPICS = frozenset({"/rosout", "/parameter_events"})
ROS2_PARAMETER_SERVICES = ("describe_parameters", "get_parameter_types", "get_parameters", "list_parameters",
                           "set_parameters", "set_parameters_atomically", "get_type_description")
# the QoS values ROS 2 gives a policy by default; an observation and a recovery list the others
ROS2_QOS_DEFAULTS = {"reliability": "reliable", "durability": "volatile", "liveliness": "automatic"}
ROS2_SECTIONS = {"Subscribers:": "subscribers", "Publishers:": "publishers", "Service Servers:": "services",
                 "Service Clients:": None, "Action Servers:": None, "Action Clients:": None}


@dataclass(frozen=True)
class Architecture:
    """`kinds` are those the observation can see: a ROS 1 master has no clients, actions or QoS, a
    live ROS 2 graph has them all (ROS2_KINDS). JSON holds only those kinds."""

    nodes: frozenset[str]
    publishers: frozenset[tuple[str, str, str]]
    subscribers: frozenset[tuple[str, str, str]]
    services: frozenset[tuple[str, str]]
    clients: frozenset[tuple[str, str]] = frozenset()
    action_servers: frozenset[tuple[str, str]] = frozenset()
    action_clients: frozenset[tuple[str, str]] = frozenset()
    qos: frozenset[tuple[str, str, str, str, str]] = frozenset()  # (node, topic, publisher|subscriber, policy, value)
    kinds: tuple[str, ...] = KINDS

    ROS2_KINDS: ClassVar[tuple[str, ...]] = KINDS + ("clients", "action_servers", "action_clients", "qos")

    def to_json(self) -> str:
        return json.dumps({k: sorted(map(list, getattr(self, k))) if k != "nodes" else sorted(self.nodes)
                           for k in self.kinds}, indent=1) + "\n"

    @classmethod
    def merged(cls, parts: list[Architecture]) -> Architecture:
        kinds = tuple(k for k in cls.ROS2_KINDS if any(k in a.kinds for a in parts))
        return cls(**{k: frozenset().union(*(getattr(a, k) for a in parts)) for k in kinds}, kinds=kinds)

    @classmethod
    def from_json(cls, text: str) -> Architecture:
        data = json.loads(text)
        kinds = KINDS + tuple(k for k in cls.ROS2_KINDS[len(KINDS):] if k in data)
        rows: dict[str, Any] = {k: frozenset(data[k]) if k == "nodes" else frozenset(map(tuple, data[k]))
                                for k in kinds}
        return cls(**rows, kinds=kinds)

    def restricted(self, nodes: set[str] | frozenset[str]) -> Architecture:
        """The part of the architecture on `nodes`: those nodes and their ports."""
        ports: dict[str, Any] = {k: frozenset(r for r in getattr(self, k) if r[0] in nodes) for k in self.ROS2_KINDS[1:]}
        return replace(self, nodes=self.nodes & nodes, **ports)

    def compared(self) -> dict[str, frozenset]:
        """What a comparison looks at: subscribers without their (master-side ambiguous) type."""
        every = {k: getattr(self, k) for k in self.ROS2_KINDS}
        return {**every, "subscribers": frozenset((n, t) for n, t, _ty in self.subscribers)}


class _Transport(xmlrpc.client.Transport):
    def make_connection(self, host):
        connection = super().make_connection(host)
        connection.timeout = 5.0
        return connection


def master(uri: str) -> xmlrpc.client.ServerProxy:
    return xmlrpc.client.ServerProxy(uri, transport=_Transport())


def call(method, *args):
    code, message, value = method(CALLER_ID, *args)
    if code != 1:
        raise RuntimeError(f"master call failed: {message}")
    return value


def read_master(proxy: xmlrpc.client.ServerProxy) -> Architecture:
    """The computation graph registered on the master, minus infrastructure."""
    pubs, subs, srvs = call(proxy.getSystemState)
    types = dict(call(proxy.getTopicTypes))
    nodes = {n for _, members in pubs + subs + srvs for n in members} - INFRA_NODES

    def edges(entries: list) -> frozenset[tuple[str, str, str]]:
        return frozenset((n, t, types.get(t, "")) for t, members in entries if t not in INFRA_TOPICS
                         for n in members if n in nodes)

    services = frozenset((n, s) for s, members in srvs for n in members
                         if n in nodes and s not in {f"{n}/{x}" for x in LOGGER_SERVICES})
    return Architecture(frozenset(nodes), edges(pubs), edges(subs), services)


class NodeInfoError(ValueError):
    """A line of saved `ros2 node info` output that does not fit its format."""


def read_ros2_node_info(text: str, file: str) -> Architecture:
    """The nodes in saved `ros2 node info NODE` outputs (several may be concatenated), minus
    infrastructure (/rosout, /parameter_events, parameter services). Clients and actions are skipped:
    the shape has no place for them."""
    nodes: set[str] = set()
    found: dict[str, set] = {"publishers": set(), "subscribers": set(), "services": set()}
    node = section = None
    for number, line in enumerate(text.splitlines(), 1):
        stripped = line.strip()
        if not stripped:
            continue
        if not line[0].isspace():
            if not stripped.startswith("/"):
                raise NodeInfoError(f"{file}:{number}: expected a node name such as /talker, got {stripped!r}")
            node, section = stripped, None
            nodes.add(node)
        elif stripped in ROS2_SECTIONS:
            section = ROS2_SECTIONS[stripped] or ""
        elif node is None or section is None or ": " not in stripped:
            raise NodeInfoError(f"{file}:{number}: expected 'NAME: TYPE' under a section, got {stripped!r}")
        elif section:
            name, type_ = stripped.split(": ", 1)
            if section == "services":
                if name not in {f"{node}/{x}" for x in ROS2_PARAMETER_SERVICES}:
                    found["services"].add((node, name))
            elif name not in ROS2_INFRA_TOPICS:
                found[section].add((node, name, type_))
    return Architecture(frozenset(nodes), frozenset(found["publishers"]), frozenset(found["subscribers"]),
                        frozenset(found["services"]))


def from_facts(store: FactStore) -> Architecture:
    """The recovered architecture in the same shape (ports with unknown names left out, and the
    ports marked `infrastructure_port`, which an observation keeps apart too)."""
    infrastructure = {r[0] for r in store.rows("infrastructure_port")}

    def rows(relation: str, typed: bool) -> frozenset:
        return frozenset((str(n), t, ty if isinstance(ty, str) else "") if typed else (str(n), str(t))
                         for p, n, t, ty in store.rows(relation) if not isinstance(t, Unknown) and p not in infrastructure)

    return Architecture(frozenset(str(r[0]) for r in store.rows("node")), rows("publisher", True),
                        rows("subscriber", True), rows("service_server", False), rows("service_client", False),
                        rows("action_server", False), rows("action_client", False), _qos_from_facts(store),
                        Architecture.ROS2_KINDS)


def _qos_from_facts(store: FactStore) -> frozenset[tuple[str, str, str, str, str]]:
    """(node, topic, publisher|subscriber, policy, value) of the non-default QoS policies an
    observation reports: reliability, durability and liveliness, and durations in microseconds."""
    ends = {p: (str(n), str(t), relation) for relation in ("publisher", "subscriber")
            for p, n, t, _ty in store.rows(relation) if not isinstance(t, Unknown)}
    found = {(*ends[p], str(policy), str(value)) for p, policy, value in store.rows("qos")
             if p in ends and policy in ROS2_QOS_DEFAULTS and value != ROS2_QOS_DEFAULTS[policy]}
    found |= {(*ends[p], str(policy), str(micros)) for p, policy, micros in store.rows("qos_duration")
              if p in ends and not (policy == "lifespan" and ends[p][2] == "subscriber")}
    return frozenset(found)


def compare(recovered: Architecture, observed: Architecture) -> dict[str, dict]:
    """Per kind the observation can see: counts, over- and under-approximation (as in the
    ROSDiscover paper's Table IV: both divided by the observed count, so over-approximation may
    exceed 100), and the differences."""
    result = {}
    ours, theirs = recovered.compared(), observed.compared()
    for kind in observed.kinds:
        extra, missing = sorted(ours[kind] - theirs[kind]), sorted(theirs[kind] - ours[kind])
        result[kind] = {
            "recovered": len(ours[kind]), "observed": len(theirs[kind]),
            "over_approximation": round(100 * len(extra) / len(theirs[kind]), 1) if theirs[kind] else 0.0,
            "under_approximation": round(100 * len(missing) / len(theirs[kind]), 1) if theirs[kind] else 0.0,
            "only_recovered": [list(x) if isinstance(x, tuple) else x for x in extra],
            "only_observed": [list(x) if isinstance(x, tuple) else x for x in missing],
        }
    return result


def write_models(observed: Architecture, folder: Path, skip: frozenset[str] = frozenset()) -> list[Path]:
    """One instance model per observed node (except `skip`): its topics as the master saw them.
    Service types are not on the master, so services are listed in a comment."""
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for node in sorted(observed.nodes - skip):
        model = {"instance": node,
                 "publishers": [{"name": t, "type": ty} for n, t, ty in sorted(observed.publishers) if n == node],
                 "subscribers": [{"name": t, "type": ty} for n, t, ty in sorted(observed.subscribers) if n == node]}
        services = [s for n, s in sorted(observed.services) if n == node]
        path = folder / (node.strip("/").replace("/", "__") + ".yaml")
        header = "# observed by archlog from a running master; check it before use\n"
        if services:
            header += "# services (types unknown to the master): " + ", ".join(services) + "\n"
        path.write_text(header + yaml.safe_dump(model, sort_keys=False), encoding="utf-8")
        written.append(path)
    return written
