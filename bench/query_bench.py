"""Benchmark: REPL-style queries against already loaded facts (target: <= 50 ms each).

    python bench/query_bench.py
"""

from __future__ import annotations

import json
import statistics
from pathlib import Path

from archlog.analysis import analyse
from archlog.queries.session import Session
from archlog.rules.ruleset import load_rules

ROOT = Path(__file__).resolve().parent.parent
GOALS = [
    "publisher(P, N, T, Ty)",
    "subscriber(_, N, T, _), not published(T)",
    "publisher(_, N, T, _), publisher(_, M, T, _), N != M",
    "near_miss(T, P, N, R, T2, Q, M, R2, D)",
    "queue_size(P, S), port_node(P, N)",
]


def main() -> None:
    times, grounding = [], []
    for case in sorted((ROOT / "corpus" / "ros1").glob("*/*/case.json")):
        spec = json.loads(case.read_text())
        session = Session(analyse([case.parent], spec["launch"], spec.get("args", {}), []).store, load_rules([]))
        grounding.append(session.ground_seconds)
        times += [session.query(goal).seconds for goal in GOALS]
    print(f"{len(times)} queries over {len(grounding)} systems: median {statistics.median(times) * 1000:.1f} ms, "
          f"max {max(times) * 1000:.1f} ms; grounding the rules once per system: median "
          f"{statistics.median(grounding) * 1000:.1f} ms")


if __name__ == "__main__":
    main()
