"""Benchmark: the shipped rules on a large synthetic system where part is unknown (issue 21).

    python bench/partial_bench.py [NODES]

NODES node instances (default 2000) with four ports each, one message type per topic out of 40;
one node in ten is opaque (no source) and is remapped onto one name, one in twenty was extracted
incompletely, one in twenty-five has a publisher of unknown type whose name is known to end with
a topic's (`host + '/topicN'`), and the subscribers of one node in three are dangling. Prints the
time to ground and solve, and the findings per rule, so that per-name gating (opaque_near,
opaque_other, may_name) can be checked not to grow with the product of names and nodes.
"""

from __future__ import annotations

import sys
import time
from collections import Counter

from archlog.facts.patterns import add_name_fits
from archlog.facts.store import FactStore
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules
from archlog.values import Unknown


def synthetic(nodes: int) -> FactStore:
    store = FactStore()
    for i in range(nodes):
        node, elem = f"/n{i}", f"e{i}"
        store.add("node", node, "pkg", f"exe{i % 50}", elem)
        store.locate(elem, "system.launch", i + 1)
        if i % 10 == 0:
            store.add("remap", f"r{i}", node, "/in", f"/topic{i}")
            continue
        store.add("node_source", node, "cpp")
        if i % 20 == 1:
            store.add("node_incomplete", node, "does not compile")
        for k, kind in enumerate(("publisher", "subscriber", "publisher", "subscriber")):
            port = f"p{i}_{k}"
            index = (i + k) % (nodes // 2) if kind == "publisher" or i % 3 else nodes + i
            store.add(kind, port, node, f"/topic{index}", f"msgs/T{index % 40}")
            store.locate(port, f"src/n{i}.cpp", 10 + k)
        if i % 25 == 2:  # a port whose name is known only in part, of an unknown type
            name = Unknown(f"host + '/topic{i}'", f"src/n{i}.cpp", 20, "", f"/topic{i}")
            store.add("publisher", f"p{i}_u", node, name, Unknown("message class", f"src/n{i}.cpp", 20))
            store.add("unknown_pattern", name, name.prefix, name.suffix)
            store.locate(f"p{i}_u", f"src/n{i}.cpp", 20)
    add_name_fits(store)
    return store


def main() -> None:
    nodes = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
    store, engine = synthetic(nodes), Engine(load_rules([]))
    start = time.perf_counter()
    _ctl, findings = engine.run(store)
    seconds = time.perf_counter() - start
    print(f"{nodes} nodes: rules in {seconds:.2f} s; findings {dict(sorted(Counter(f.rule.id for f in findings).items()))}")


if __name__ == "__main__":
    main()
