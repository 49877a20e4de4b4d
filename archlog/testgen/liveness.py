"""Which outputs must follow their required inputs: the liveness half of the `requires` property,
asserted only where the behavior facts decide it. An output follows when one of its publish calls is
decided by its trigger and guards alone (`decided`), is reached periodically (a loop or timer of known
period) or from a required input's callback without guards, and every guard is made true by a
required input's callback and made false by nothing but start-up code. Anything else (a comparison
of a message's field on the way, a guard another callback or the loop resets, C++ whose paths are
not decided) is undecided: only the safety half (silent until the input came) is checked."""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass

from archlog.facts.store import FactStore


@dataclass
class Output:
    """One watched output of a node: its publisher port and the open inputs it requires."""

    node: str
    port: str
    topic: str
    inputs: list[str]


def follows(store: FactStore, output: Output) -> float | str:
    """The period within which `output` must follow once its inputs were sent (0.0: at once, from the
    input's callback), or why that is not decided (a string)."""
    decided = {str(r[0]) for r in store.rows("decided")}
    topics = {str(pid): str(topic) for pid, node, topic, _ty in store.rows("subscriber") if str(node) == output.node}
    feeding = {pid for pid, topic in topics.items() if topic in output.inputs}
    periods = {str(pid): seconds(period) for pid, node, period in store.rows("timer") if str(node) == output.node}
    loops = {str(call): seconds(period) for call, period in store.rows("loop_period")}
    triggers, guards = defaultdict(list), defaultdict(list)
    for call, kind, source in store.rows("publish_trigger"):
        triggers[str(call)].append((str(kind), str(source)))
    for call, var, value, _gid in store.rows("publish_guard"):
        guards[str(call)].append((str(var), str(value)))
    writes = [(str(w), str(var), str(value), str(source)) for w, node, var, value, source in store.rows("state_write")
              if str(node) == output.node]
    calls = [str(c) for c, node, pub in store.rows("publish_call") if str(node) == output.node and str(pub) == output.port]
    found: list[float] = []
    for call in calls:
        if call not in decided or not all(_made_true(var, value, writes, decided, feeding) for var, value in guards[call]):
            continue
        for kind, source in triggers[call]:
            period = loops.get(call) if kind == "loop" else periods.get(source) if kind == "timer" else \
                0.0 if kind == "callback" and source in feeding and not guards[call] else None
            if period is not None:
                found.append(period)
    if found:
        return min(found)
    return (f"whether {output.topic} follows {', '.join(output.inputs)} depends on more than archlog models "
            "(a condition on the way to its publish call, or state another trigger may reset)")


def _made_true(var: str, value: str, writes: list[tuple[str, str, str, str]], decided: set[str],
               feeding: set[str]) -> bool:
    """A guard `var == value` that a required input's callback makes true and only start-up code
    makes otherwise."""
    mine = [w for w in writes if w[1] == var]
    setters = [w for w, _v, written, source in mine if written == value and w in decided and source in feeding]
    resets = [w for w, _v, written, source in mine if written != value and (source != "none" or w not in decided)]
    return bool(setters) and not resets


def seconds(value: object) -> float | None:
    """A positive number of seconds, or None."""
    try:
        seconds = float(str(value))
    except ValueError:
        return None
    return seconds if seconds > 0 else None
