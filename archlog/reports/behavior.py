"""Each node instance's behavior as a small state machine: its state variables (initial value, and
the callbacks that set them), and for each output the triggers and guards of its publish calls and
the inputs it requires (derived by the rules). Text for terminals, a dict for JSON."""

from __future__ import annotations

from collections import defaultdict

import clingo
from rich.console import Console

from archlog.facts.store import FactStore
from archlog.rules.engine import render

Model = list[dict]


def behavior_model(store: FactStore, ctl: clingo.Control) -> Model:
    """One entry per node instance that has outputs or state, in name order."""
    ports = _ports(store)
    required: dict[str, list[str]] = defaultdict(list)
    for atom in ctl.symbolic_atoms.by_signature("required_topic", 2):
        pub, topic = (render(store.from_term(a)) for a in atom.symbol.arguments)
        required[pub].append(topic)
    triggers = defaultdict(list)
    for call, kind, source in store.rows("publish_trigger"):
        triggers[call].append(_trigger(str(kind), str(source), ports, store))
    for call, period in store.rows("loop_period"):
        for trigger in triggers[call]:
            if trigger["kind"] == "loop":
                trigger["period"] = render(period)
    guards = defaultdict(list)
    for call, var, value, gid in store.rows("publish_guard"):
        guards[call].append({"var": var, "value": value, **_where(store, str(gid))})
    nodes: dict[str, dict] = {}
    for call, node, port in store.rows("publish_call"):
        pub = str(port)
        entry = _node(nodes, str(node), store)
        output = entry["outputs"].setdefault(pub, {**ports.get(pub, {"name": "?", "type": "?"}), **_where(store, pub),
                                                   "calls": [], "requires": sorted(set(required.get(pub, [])))})
        output["calls"].append({**_where(store, str(call)), "triggers": triggers[call], "guards": guards[call]})
    for wid, node, var, value, source in store.rows("state_write"):
        state = _node(nodes, str(node), store)["state"].setdefault(var, {"var": var, "initial": None, "set_by": []})
        if source == "none":
            state["initial"] = value
        else:
            state["set_by"].append({"value": value, "by": ports.get(str(source), {}).get("name", "?"),
                                     **_where(store, str(wid))})
    return [{**entry, "outputs": list(entry["outputs"].values()), "state": list(entry["state"].values())}
            for _name, entry in sorted(nodes.items())]


def print_behavior(model: Model, console: Console) -> None:
    """Triggers, guards and required inputs of every output, and how the state is set."""
    for node in model:
        console.print(f"[bold]{node['node']}[/bold] ({node['source']})")
        for state in node["state"]:
            sets = "".join(f"; on {s['by']}: {s['value']} ({s['file']}:{s['line']})" for s in state["set_by"])
            console.print(f"  state {state['var']} = {state['initial'] or '?'}{sets}", markup=False)
        for output in node["outputs"]:
            console.print(f"  output {output['name']} ({output['type']}) {output['file']}:{output['line']}",
                          markup=False)
            for call in output["calls"]:
                how = ", ".join(_describe(t) for t in call["triggers"]) or "trigger unknown"
                when = " and ".join(f"{g['var']}={g['value']}" for g in call["guards"])
                condition = f" when {when}" if when else ""
                console.print(f"    publishes at {call['file']}:{call['line']} {how}{condition}", markup=False)
            if output["requires"]:
                console.print(f"    requires {', '.join(output['requires'])}", markup=False)


def _ports(store: FactStore) -> dict[str, dict]:
    """Port id -> its name (topic, service or timer period) and type."""
    found: dict[str, dict] = {}
    for relation in ("publisher", "subscriber", "service_server", "action_server"):
        for pid, _node, name, type_ in store.rows(relation):
            found[str(pid)] = {"name": render(name), "type": render(type_), "kind": relation}
    for pid, _node, period in store.rows("timer"):
        found[str(pid)] = {"name": f"{render(period)} s", "type": "", "kind": "timer"}
    return found


def _trigger(kind: str, source: str, ports: dict[str, dict], store: FactStore) -> dict:
    trigger = {"kind": kind}
    if source != "none":
        trigger.update(by=ports.get(source, {}).get("name", "?"), **_where(store, source))
    return trigger


def _describe(trigger: dict) -> str:
    kind, by, period = trigger["kind"], trigger.get("by"), trigger.get("period")
    if kind == "timer":
        return f"on a timer every {by}" if by else "on a timer"
    if kind == "callback":
        return f"when {by} arrives"
    if kind == "loop":
        return f"in a loop every {period} s" if period else "in a loop"
    return "at start-up" if kind == "startup" else "trigger unknown"


def _node(nodes: dict[str, dict], node: str, store: FactStore) -> dict:
    if node not in nodes:
        source = next((origin for name, origin in store.rows("node_source") if name == node), "?")
        nodes[node] = {"node": node, "source": source, "outputs": {}, "state": {}}
    return nodes[node]


def _where(store: FactStore, fact_id: str) -> dict:
    found = store.location(fact_id)
    return {"file": found[0], "line": found[1]} if found else {"file": "", "line": 0}
