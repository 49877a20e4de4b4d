"""The behavior model of a system: for every output (a node's publisher of a topic), the triggers
of its publish calls and the topics it requires; recovered from archlog's facts and derived
relations, or read from a corpus case's `behavior` key."""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass
from pathlib import Path

import clingo

from archlog.analysis import Analysis
from archlog.facts.store import FactStore
from archlog.rules.engine import render

Key = tuple[str, str]  # (node, output topic)


@dataclass(frozen=True)
class Output:
    node: str
    output: str
    triggers: frozenset[str]
    requires: frozenset[str]

    def row(self) -> tuple[str, str, list[str], list[str]]:
        return self.node, self.output, sorted(self.triggers), sorted(self.requires)


Model = dict[Key, Output]


def expected_behavior(case: dict) -> Model:
    """The `behavior` key of a case.json; each (node, output) at most once."""
    model: Model = {}
    for entry in case["behavior"]:
        key = (entry["node"], entry["output"])
        assert key not in model, f"{key} listed twice in the expected behavior"
        model[key] = Output(entry["node"], entry["output"], frozenset(entry["triggers"]),
                            frozenset(entry["requires"]))
    return model


def recovered_behavior(store: FactStore, ctl: clingo.Control) -> Model:
    """Every publisher port of the system, with the triggers of the publish calls on it
    (publish_trigger) and the topics it requires (the derived relation required_topic)."""
    port_key: dict[str, Key] = {}
    for pid, node, topic, _type in store.rows("publisher"):
        port_key[str(pid)] = (render(node), render(topic))
    call_port = {str(call): str(pub) for call, _node, pub in store.rows("publish_call")}
    triggers: dict[Key, set[str]] = defaultdict(set)
    for call, trigger, _source in store.rows("publish_trigger"):
        pub = call_port.get(str(call))
        if pub in port_key:
            triggers[port_key[pub]].add(str(trigger))
    requires: dict[Key, set[str]] = defaultdict(set)
    for atom in ctl.symbolic_atoms.by_signature("required_topic", 2):
        pub, topic = (store.from_term(a) for a in atom.symbol.arguments)
        if str(pub) in port_key:
            requires[port_key[str(pub)]].add(render(topic))
    return {key: Output(key[0], key[1], frozenset(triggers[key]), frozenset(requires[key]))
            for key in sorted(set(port_key.values()))}


def analysis_behavior(analysis: Analysis) -> Model:
    """The recovered model of an analysed system, with archlog's built-in rules grounded."""
    from archlog.rules.engine import Engine
    from archlog.rules.ruleset import load_rules

    ctl = Engine(load_rules([])).ground(analysis.store)
    return recovered_behavior(analysis.store, ctl)


def silenced_outputs(model: Model, fed: frozenset[str] = frozenset()) -> set[Key]:
    """The outputs that cannot be published: those that require a topic nothing in the system
    publishes (and that is not in `fed`, topics published from outside), or (transitively) a
    topic whose every publisher is silenced. The complement of the least fixpoint of live
    outputs, as the prelude's live_pub."""
    publishers: dict[str, set[Key]] = defaultdict(set)
    for key in model:
        publishers[key[1]].add(key)
    live: set[Key] = set()
    changed = True
    while changed:
        changed = False
        for key, out in model.items():
            if key not in live and all(t in fed or publishers[t] & live for t in out.requires):
                live.add(key)
                changed = True
    return set(model) - live


def describe(model: Model) -> list[tuple[str, str, list[str], list[str]]]:
    return [model[key].row() for key in sorted(model)]


def case_dir(variant: Path) -> str:
    return f"{variant.parent.name}/{variant.name}"
