"""What a generated test needs to know of the recovered configuration, as plain JSON-able data:
the nodes under test, their open inputs and outputs with types, the services and actions they provide
that no node of the configuration calls (open services and actions: the test calls them and sends
them goals), the recovered interface (ROS 2: with its action servers), the
built-in ports of the nodes under test (not compared with the live graph), the lifecycle nodes
(configured and activated after each start, as a deployment would), the periodic outputs, the inputs
each output requires and those it must follow (liveness.py), the parameters the nodes read, and the
message definitions of the inputs' types, of the services' requests and of the actions' goals (outputs are recorded by
the bridge with the installed message classes). A configuration whose types are ROS 2's (`pkg/msg/Name`) is `"ros": 2`; its model
also holds how to start each node under test (package, executable, remaps, the configuration's
parameters, its Python script or entry point), as a ROS 2 test starts them itself, and the QoS its
publishers must offer; a ROS 1 model the Python script of each node under test that is one (roslaunch
runs it under coverage.py)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import clingo

from archlog.analysis import Analysis, resolve_launch
from archlog.facts.store import FactStore
from archlog.observe import KINDS, Architecture, from_facts
from archlog.reports.behavior import behavior_model
from archlog.testgen.liveness import Output, follows, seconds
from archlog.testgen.msgspec import message_specs
from archlog.values import Unknown

INFRA_TOPICS = frozenset({"/rosout", "/rosout_agg", "/clock"})


class ModelError(ValueError):
    """The configuration cannot be tested as asked (an unknown node name, nothing to feed or watch)."""


def test_model(analysis: Analysis, ctl: clingo.Control, paths: list[Path], launches: list[str],
               args: dict[str, str], nodes: list[str] | None = None) -> dict[str, Any]:
    """The model of the configuration, or of `nodes` in isolation (then every input of theirs is open)."""
    store = analysis.store
    everyone = sorted(str(r[0]) for r in store.rows("node"))
    chosen = everyone if not nodes else [n if n.startswith("/") else f"/{n}" for n in nodes]
    unknown = sorted(set(chosen) - set(everyone))
    if unknown:
        raise ModelError(f"no node {', '.join(unknown)} in the configuration (nodes: {', '.join(everyone)})")
    groups = {r[0]: str(r[1]) for r in store.rows("infrastructure_port")}
    builtin = set(groups)  # the client library's own ports: not under test
    own = {rel: {(str(n), str(name)) for p, n, name, _ty in store.rows(rel) if p in builtin and str(n) in chosen}
           for rel in ("publisher", "subscriber", "service_server", "service_client")}
    lifecycle = sorted({str(n) for p, n, _name, _ty in store.rows("service_server")
                        if groups.get(p) == "lifecycle" and str(n) in chosen})
    ports = {rel: [(str(p), str(n), t, ty) for p, n, t, ty in store.rows(rel)
                   if not isinstance(t, Unknown) and t not in INFRA_TOPICS and p not in builtin]
             for rel in ("publisher", "subscriber")}
    published = {t for _p, _n, t, _ty in ports["publisher"]}
    subscribed = {t for _p, _n, t, _ty in ports["subscriber"]}
    called = {str(s) for _p, _n, s, _ty in store.rows("service_client")}
    services = {str(s): str(ty) for p, n, s, ty in store.rows("service_server")
                if str(n) in chosen and p not in builtin and isinstance(s, str) and isinstance(ty, str)
                and (nodes or str(s) not in called)}
    goals = {str(a) for _p, _n, a, _ty in store.rows("action_client")}
    actions = {str(a): str(ty) for p, n, a, ty in store.rows("action_server")
               if str(n) in chosen and p not in builtin and isinstance(a, str) and isinstance(ty, str)
               and "/action/" in ty and (nodes or str(a) not in goals)}
    inputs = {str(t): str(ty) for _p, n, t, ty in ports["subscriber"]
              if n in chosen and (nodes or t not in published) and isinstance(ty, str)}
    outputs = {str(t): str(ty) for _p, n, t, ty in ports["publisher"]
               if n in chosen and (nodes or t not in subscribed) and isinstance(ty, str)}
    where: dict[str, tuple[str, int]] = {}  # input type -> file and line of a subscriber using it
    for pid, n, t, ty in ports["subscriber"]:
        if t in inputs and n in chosen:
            where.setdefault(str(ty), (store.location(pid) or ("", 0, 0))[:2])
    for relation, served in (("service_server", services), ("action_server", actions)):
        for server, node, name, kind in store.rows(relation):
            if name in served and node in chosen:
                where.setdefault(str(kind), (store.location(str(server)) or ("", 0, 0))[:2])
    periodic, requires, follow, undecided = _behavior(analysis, ctl, chosen, outputs, inputs)
    params = {str(name): (None if isinstance(default, Unknown) else str(default))
              for _p, n, name, default in store.rows("param_read") if str(n) in chosen and not isinstance(name, Unknown)}
    ros = 2 if any(f"/{kind}/" in ty for ty in (*inputs.values(), *outputs.values(), *services.values(), *actions.values())
                   for kind in ("msg", "srv", "action")) else 1
    part = from_facts(store).restricted(set(chosen))  # ROS 2: action servers too, as the live graph shows them
    interface = Architecture(frozenset(chosen), part.publishers, part.subscribers, part.services,
                             action_servers=part.action_servers if ros == 2 else frozenset(),
                             kinds=(*KINDS, "action_servers") if ros == 2 else KINDS)
    return {
        "ros": ros,
        "commands": _commands(analysis, chosen) if ros == 2 else [],
        "scripts": _scripts(analysis, chosen) if ros == 1 else {},
        "qos": _qos(store, chosen, inputs) if ros == 2 else {},
        "paths": [str(p.resolve()) for p in paths],
        "launch": [str(resolve_launch(spec, analysis.workspace).resolve()) for spec in launches],
        "args": dict(args),
        "nodes": chosen,
        "isolated": bool(nodes),
        "inputs": dict(sorted(inputs.items())),
        "outputs": dict(sorted(outputs.items())),
        "services": dict(sorted(services.items())),
        "actions": dict(sorted(actions.items())),
        "interface": interface.to_json(),
        "builtin": sorted([n, name] for ports in own.values() for n, name in ports),
        "lifecycle": lifecycle,
        "periodic": periodic,
        "requires": requires,
        "follows": follow,
        "undecided": undecided,
        "params": dict(sorted(params.items())),
        "specs": message_specs(analysis.workspace, where, analysis.diagnostics),
    }


def _commands(analysis: Analysis, chosen: list[str]) -> list[dict[str, Any]]:
    """How to start each process of the nodes under test (one per launch entity: a program may hold
    several nodes): its nodes, package, executable, remaps, the configuration's parameters of its nodes
    with their types (resolved names; those with unknown parts left out), and for a Python executable
    of the workspace its script or console_scripts entry point (run without ros2cli)."""
    store, known = analysis.store, (str, int, float)
    remaps: dict[str, list[list[str]]] = {}
    for _e, node, source, target in store.rows("remap"):
        if isinstance(source, str) and isinstance(target, str):
            remaps.setdefault(str(node), []).append([source, target])
    params = [(name, value) for name, value, _e in store.rows("param") if isinstance(name, str) and isinstance(value, known)]
    processes: dict[str, list[tuple[str, str, str]]] = {}  # launch entity -> its nodes (one process)
    for node, pkg, exe, entity in store.rows("node"):
        processes.setdefault(str(entity), []).append((str(node), str(pkg), str(exe)))
    commands = []
    for nodes in processes.values():
        names = [n for n, _pkg, _exe in nodes]
        if set(names) & set(chosen):
            _name, pkg, exe = nodes[0]
            commands.append({"name": names[0], "nodes": names, "pkg": pkg, "exe": exe,
                             "remaps": [r for n in names for r in remaps.get(n, [])],
                             "params": {name: value for name, value in params
                                        if any(name.startswith(f"{n}/") for n in names)},
                             **_python_start(analysis, pkg, exe)})
    return commands


def _scripts(analysis: Analysis, chosen: list[str]) -> dict[str, str]:
    """The Python script of each ROS 1 node under test that is one (its line coverage is measured)."""
    scripts = {str(node): _python_start(analysis, str(pkg), str(exe)).get("script") for node, pkg, exe, _e
               in analysis.store.rows("node") if str(node) in chosen}
    return {node: script for node, script in sorted(scripts.items()) if script}


def _python_start(analysis: Analysis, pkg: str, exe: str) -> dict[str, str]:
    """{"script": path} or {"entry": "module:function", "root": the folder it imports from}, or {}."""
    executable = analysis.workspace.executable(pkg, exe)
    if executable is None or executable.lang != "python" or not executable.sources:
        return {}
    source = executable.sources[0].resolve()
    if not executable.entry:
        return {"script": str(source)}
    depth = len(executable.entry.partition(":")[0].split(".")) + (source.name == "__init__.py")
    return {"entry": executable.entry, "root": str(source.parents[depth - 1])}


def _qos(store: FactStore, chosen: list[str], inputs: dict[str, str]) -> dict[str, dict[str, Any]]:
    """For each open input, the QoS the test's publisher must offer to match every subscriber of the
    nodes under test: transient_local and a manual liveliness when one asks for it, the shortest
    deadline and liveliness lease asked for (seconds)."""
    subscribers = {str(pid): str(topic) for pid, node, topic, _ty in store.rows("subscriber")
                   if str(node) in chosen and str(topic) in inputs}
    offered: dict[str, dict[str, Any]] = {}
    for pid, policy, value in store.rows("qos"):
        topic = subscribers.get(str(pid))
        if topic is not None and (policy, value) in (("durability", "transient_local"), ("liveliness", "manual_by_topic")):
            offered.setdefault(topic, {})[str(policy)] = str(value)
    for pid, policy, microseconds in store.rows("qos_duration"):
        topic = subscribers.get(str(pid))
        if topic is not None and policy in ("deadline", "liveliness_lease_duration") and isinstance(microseconds, int):
            wanted = offered.setdefault(topic, {})
            wanted[str(policy)] = min(wanted.get(str(policy), microseconds / 1e6), microseconds / 1e6)
    return dict(sorted(offered.items()))


def _behavior(analysis: Analysis, ctl: clingo.Control, chosen: list[str], outputs: dict[str, str],
              inputs: dict[str, str]) -> tuple[dict[str, float], dict[str, list[str]], dict[str, float], dict[str, str]]:
    """Watched outputs published only by timers or loops of known period, with no guard and no
    required input (topic -> the slowest period); the open inputs each watched output requires; the
    outputs that must follow them (topic -> within which period, see liveness.py); and why the others
    need not (topic -> reason)."""
    periodic: dict[str, float] = {}
    requires: dict[str, list[str]] = {}
    follow: dict[str, float] = {}
    undecided: dict[str, str] = {}
    ports = {(str(n), str(t)): str(p) for p, n, t, _ty in analysis.store.rows("publisher")}
    for node in behavior_model(analysis.store, ctl):
        if node["node"] not in chosen:
            continue
        for output in node["outputs"]:
            topic = output["name"]
            if topic not in outputs:
                continue
            required = [t for t in output["requires"] if t in inputs]
            if required:
                requires[topic] = required
                within = follows(analysis.store, Output(node["node"], ports.get((node["node"], topic), ""), topic, required))
                if isinstance(within, str) or set(output["requires"]) - set(required):
                    undecided[topic] = within if isinstance(within, str) else \
                        f"{topic} also requires inputs of nodes not under test"
                else:
                    follow[topic] = within
            periods = [_trigger_period(t) for call in output["calls"] for t in call["triggers"]]
            if periods and None not in periods and not output["requires"] \
                    and not any(call["guards"] for call in output["calls"]):
                periodic[topic] = max(p for p in periods if p is not None)
    return periodic, requires, follow, undecided


def _trigger_period(trigger: dict) -> float | None:
    """A loop's period, or a timer's (its port is named "PERIOD s" in the behavior model)."""
    if trigger["kind"] == "loop":
        return seconds(trigger.get("period"))
    if trigger["kind"] == "timer":
        return seconds(str(trigger.get("by", "")).removesuffix(" s"))
    return None
