"""Ports whose message type follows another topic's: a model's `type: {like: NAME}` (topic_tools'
relay, throttle, drop, mux and demux publish whatever their input carries). Once every instance's
ports are known, such a port gets the type the configuration's publishers of its input topics give;
when they give none of a known type, or disagree, its type stays unknown (never guessed). A relay's
input may be another relay's output, so the types settle in rounds, at most one per such port."""

from __future__ import annotations

from dataclasses import dataclass

from archlog.facts.store import FactStore
from archlog.values import Unknown


@dataclass(frozen=True)
class Following:
    """A port (its fact id, relation, node and resolved name) that carries the type of the publishers
    of `inputs` (resolved names); `unknown` locates the type when it stays unknown."""

    pid: str
    relation: str
    node: str
    name: str | Unknown
    inputs: tuple[str | Unknown, ...]
    unknown: Unknown


def add_followed(store: FactStore, following: list[Following]) -> None:
    """The fact rows of the ports that follow another topic's type, typed from the store's publishers."""
    wanted = {topic for port in following for topic in port.inputs}
    fixed: dict[str, set[str]] = {}
    for _pid, _node, topic, published in store.rows("publisher") if wanted else ():
        if topic in wanted and isinstance(topic, str) and isinstance(published, str):
            fixed.setdefault(topic, set()).add(published)
    types: list[str | None] = [None] * len(following)
    known = fixed
    for _round in range(len(following)):
        known = {topic: set(found) for topic, found in fixed.items()}
        for port, type_ in zip(following, types):
            if type_ is not None and port.relation == "publisher" and isinstance(port.name, str) \
                    and port.name in wanted:
                known.setdefault(port.name, set()).add(type_)
        settled = [_single(port, known) for port in following]
        if settled == types:
            break
        types = settled
    for port, type_ in zip(following, types):
        store.add(port.relation, port.pid, port.node, port.name, type_ or _unknown(port, known))


def _single(port: Following, known: dict[str, set[str]]) -> str | None:
    """The one known type the publishers of the port's inputs give, else None."""
    if any(isinstance(topic, Unknown) for topic in port.inputs):
        return None
    found = set().union(*(known.get(str(topic), set()) for topic in port.inputs))
    return found.pop() if len(found) == 1 else None


def _unknown(port: Following, known: dict[str, set[str]]) -> Unknown:
    inputs = ", ".join(map(str, port.inputs)) or "no topic"
    found = sorted(set().union(*(known.get(topic, set()) for topic in port.inputs if isinstance(topic, str))))
    why = f"its publishers disagree: {', '.join(found)}" if len(found) > 1 else "no publisher of a known type"
    return Unknown(f"the type of {inputs} ({why})", port.unknown.file, port.unknown.line)
