"""Benchmark: REPL-style queries against already loaded facts (target: <= 50 ms each), the first
page of rows of a large relation (target: <= 100 ms for 30,000 rows, issue 18), and `archlog repl`
start-up on a generated workspace (bench/scale_bench.py's fleet): extraction, grounding and the
banner's counts (target: <= 15 s at 10,000 nodes), then the first page of whole-relation queries.

    python bench/query_bench.py [--nodes 10000]
"""

from __future__ import annotations

import argparse
import io
import json
import statistics
import tempfile
import time
from pathlib import Path

from scale_bench import PACKAGE, generate

from archlog.analysis import analyse
from archlog.facts.store import FactStore
from archlog.queries.session import Session
from archlog.queries.table import write_table
from archlog.rules.ruleset import load_rules
from archlog.values import Unknown

ROOT = Path(__file__).resolve().parent.parent
GOALS = [
    "publisher(P, N, T, Ty)",
    "subscriber(_, N, T, _), not published(T)",
    "publisher(_, N, T, _), publisher(_, M, T, _), N != M",
    "near_miss(T, P, N, R, T2, Q, M, R2, D, O)",
    "queue_size(P, S), port_node(P, N)",
]


def corpus() -> None:
    """Each goal on each corpus system, every row read."""
    times, grounding = [], []
    for case in sorted((ROOT / "corpus" / "ros1").glob("*/*/case.json")):
        spec = json.loads(case.read_text())
        session = Session(analyse([case.parent], spec["launch"], spec.get("args", {}), []).store, load_rules([]))
        grounding.append(session.ground_seconds)
        for goal in GOALS:
            start = time.perf_counter()
            session.query(goal).read_all()
            times.append(time.perf_counter() - start)
    print(f"{len(times)} queries over {len(grounding)} systems: median {statistics.median(times) * 1000:.1f} ms, "
          f"max {max(times) * 1000:.1f} ms; grounding the rules once per system: median "
          f"{statistics.median(grounding) * 1000:.1f} ms")


def fleet(nodes: int) -> FactStore:
    """A fleet of robots with ten nodes each, their sources read (not opaque): three publishers, one
    subscriber, one parameter read (default unknown) per node, every port located."""
    store = FactStore()
    for i in range(nodes):
        robot, node = f"/robot{i // 10}", f"/robot{i // 10}/node{i % 10}"
        store.add("node", node, "pkg", f"exe{i % 10}", f"e{i}")
        store.add("node_source", node, "python")
        store.locate(f"e{i}", "fleet.launch", i + 1)
        ports = [("publisher", f"{robot}/topic{(i + k) % 10}", "std_msgs/String") for k in range(3)]
        for kind, name, type_ in [*ports, ("subscriber", f"{robot}/topic{i % 10}", "std_msgs/String")]:
            port = store.new_id("p")
            store.add(kind, port, node, name, type_)
            store.locate(port, f"src/node{i % 10}.py", 10, 1)
        port = store.new_id("p")
        store.add("param_read", port, node, f"{node}/rate", Unknown("no default", f"src/node{i % 10}.py", 4))
    return store


class FirstWrite(io.StringIO):
    """Records when the first page is flushed."""

    first: float | None = None

    def flush(self) -> None:
        if self.first is None:
            self.first = time.perf_counter()


def first_page(nodes: int) -> None:
    store = fleet(nodes)
    session = Session(store, load_rules([]))
    print(f"fleet of {nodes} nodes: {len(store.rows('publisher'))} publisher rows; grounding the rules "
          f"{session.ground_seconds:.2f} s")
    pages(session, ("publisher(P, N, T, Ty)", "param_read(P, N, X, D)", "publisher(P, N, T, _), subscriber(_, M, T, _)"))


def repl_startup(nodes: int) -> None:
    """What `archlog repl` does before its prompt, on a generated workspace of `nodes` instances."""
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp) / "fleet"
        generate(root, nodes, "fleet")
        cpu, start = time.process_time(), time.perf_counter()
        analysis = analyse([root], [f"{PACKAGE}/launch/top.launch"], {}, [root / "models.yaml"])
        extracted = time.perf_counter()
        session = Session(analysis.store, load_rules([]))
        grounded = time.perf_counter()
        facts = sum(count for _n, _a, count, kind in session.relations() if kind == "fact")
        findings = len(session.findings())
        ready = time.perf_counter()
        print(f"repl start-up, generated fleet of {nodes} nodes ({facts} facts, {findings} findings): extraction "
              f"{extracted - start:.1f} s, grounding {grounded - extracted:.1f} s, banner {ready - grounded:.1f} s; "
              f"{ready - start:.1f} s wall, {time.process_time() - cpu:.1f} s cpu until the prompt")
        pages(session, ("publisher(P, N, T, Ty)", "subscriber(P, N, T, Ty)", "location(I, F, L, C)",
                        "name_namespace(X, NS)"))


def pages(session: Session, goals: tuple[str, ...]) -> None:
    """Each goal's first page and all rows (median of 3; the first run gives clingo a relation that no
    rule reads, which later runs find there)."""
    for goal in goals:
        first, total = [], []
        for _ in range(3):
            out, start = FirstWrite(), time.perf_counter()
            result = session.query(goal)
            count = write_table(result.columns, result, out)
            first.append((out.first or time.perf_counter()) - start)
            total.append(time.perf_counter() - start)
        print(f"  {goal}: {count} rows, first page {statistics.median(first) * 1000:.1f} ms, "
              f"all rows {statistics.median(total) * 1000:.1f} ms (median of 3; first run: first page "
              f"{first[0] * 1000:.1f} ms)")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--nodes", type=int, default=10000, help="node instances of the generated fleet")
    args = parser.parse_args()
    corpus()
    first_page(args.nodes)
    repl_startup(args.nodes)


if __name__ == "__main__":
    main()
