"""The ROS 1 runtime oracle split into a tuned and a held-out part (issue 30).

Cases:
- every corpus system marked `"runtime": true` (corpus/ros1/*/{buggy,clean}): built (C++ with g++
  against Debian's ROS), launched with Debian's roslaunch on a private loopback master, its live
  graph read from the master and compared with archlog's recovery, now;
- the Debian node cases of bench/debian_nodes.py, scored from a results file of that oracle
  (`--debian`, by default bench/results/debian_nodes.json; re-running them needs Debian's source
  packages, see that script).

Scoring as bench/debian_nodes.py: ports are publishers (node, topic, type), subscribers (node,
topic) and services (node, service); missed = observed ports not recovered, extra = recovered
ports not observed, both over the observed ports of the part.

The split is fixed and does not depend on results: a case is held out when the first byte of
sha256(key) is divisible by 3 (the rule of bench/rclpy_oracle.py); the key of a corpus system is
`corpus/NAME` (both twins go together), of a Debian case `debian/CASE`. Work on recovery looks at
the tuned part only.

    python bench/ros1_heldout.py [--debian bench/results/debian_nodes.json] [--only NAME,...]
                                 [--output bench/results/ros1_heldout.json] [--reuse EARLIER.json]

`--reuse` scores the corpus systems of an earlier output again instead of launching them.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))

from support.build_cpp import build_workspace  # noqa: E402
from support.live_graph import launch_graph  # noqa: E402

from archlog.analysis import analyse, resolve_launch  # noqa: E402
from archlog.diagnostics import DiagnosticSink  # noqa: E402
from archlog.extract.workspace.index import Workspace  # noqa: E402
from archlog.observe import compare, from_facts  # noqa: E402

KINDS = ("publishers", "subscribers", "services")


def held_out(name: str) -> bool:
    """Whether a case belongs to the held-out part (fixed by its name alone; a corpus system's
    buggy and clean twins go together, by the system's name)."""
    key = name.rsplit("/", 1)[0] if name.startswith("corpus/") else name
    return hashlib.sha256(key.encode()).digest()[0] % 3 == 0


def corpus_case(variant: Path) -> dict:
    """Launch one runtime corpus system and compare its live graph with the recovery."""
    case = json.loads((variant / "case.json").read_text())
    started = time.monotonic()
    analysis = analyse([variant], case["launch"], case.get("args", {}), [variant / m for m in case.get("models", [])])
    want = from_facts(analysis.store)
    with tempfile.TemporaryDirectory() as tmp:
        src = build_workspace(variant, Path(tmp) / "ws")
        files = [resolve_launch(spec, Workspace([src.parent], DiagnosticSink())) for spec in case["launch"]]
        live = launch_graph(src, files, case.get("args", {}), expect_nodes=len(want.nodes), timeout=45)
    rows = compare(want, live)
    return {"observed": sum(rows[k]["observed"] for k in KINDS if k in rows),
            "missed": [[k, *map(str, x)] for k in KINDS if k in rows for x in rows[k]["only_observed"]],
            "extra": [[k, *map(str, x)] for k in KINDS if k in rows for x in rows[k]["only_recovered"]],
            "seconds": round(time.monotonic() - started, 1)}


def debian_cases(path: Path) -> dict[str, dict]:
    """The Debian node cases of a bench/debian_nodes.py results file (its 'own' ports)."""
    cases = json.loads(path.read_text())["cases"]
    return {f"debian/{c['case']}": {"observed": c["own"]["observed"], "missed": c["own"]["missed"],
                                    "extra": c["own"]["extra"]} for c in cases}


def totals(results: dict[str, dict]) -> dict[str, float | int]:
    observed = sum(r["observed"] for r in results.values())
    missed = sum(len(r["missed"]) for r in results.values())
    extra = sum(len(r["extra"]) for r in results.values())
    return {"cases": len(results), "observed": observed, "missed": missed, "extra": extra,
            "missed_pct": round(100 * missed / observed, 1) if observed else 0.0,
            "extra_pct": round(100 * extra / observed, 1) if observed else 0.0}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--debian", type=Path, default=ROOT / "bench" / "results" / "debian_nodes.json")
    ap.add_argument("--only", help="corpus systems to launch (NAME,...); default: every runtime system")
    ap.add_argument("--output", type=Path, default=ROOT / "bench" / "results" / "ros1_heldout.json")
    ap.add_argument("--reuse", type=Path, help="an earlier output whose corpus results are scored again, not launched")
    opts = ap.parse_args()
    variants = sorted(v.parent for v in (ROOT / "corpus" / "ros1").glob("*/*/case.json")
                      if json.loads(v.read_text()).get("runtime"))
    if opts.only:
        variants = [v for v in variants if v.parent.name in opts.only.split(",")]
    results: dict[str, dict] = {}
    if opts.reuse:
        results = {n: r for n, r in json.loads(opts.reuse.read_text())["cases"].items() if n.startswith("corpus/")}
        variants = []
    for variant in variants:
        name = f"corpus/{variant.parent.name}/{variant.name}"
        try:
            results[name] = corpus_case(variant)
        except Exception as exc:  # a system that does not come up is reported, and the run goes on
            results[name] = {"observed": 0, "missed": [], "extra": [], "error": f"{type(exc).__name__}: {exc}"}
        row = results[name]
        print(f"{name}: {row['observed']} observed, {len(row['missed'])} missed, {len(row['extra'])} extra"
              f"{' ERROR ' + row['error'] if 'error' in row else ''}", flush=True)
    if opts.debian.is_file():
        results.update(debian_cases(opts.debian))
    parts = {part: {n: r for n, r in results.items() if held_out(n) == (part == "held-out")}
             for part in ("tuned", "held-out")}
    summary = {part: {source: totals({n: r for n, r in rows.items() if n.startswith(source)})
                      for source in ("corpus/", "debian/", "")} for part, rows in parts.items()}
    opts.output.write_text(json.dumps({"summary": summary, "cases": results,
                                       "held_out": sorted(n for n in results if held_out(n))}, indent=1) + "\n")
    print("| part | source | cases | observed ports | missed | missed % | extra | extra % |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for part, sources in summary.items():
        for source, row in sources.items():
            print(f"| {part} | {source.rstrip('/') or 'all'} | {row['cases']} | {row['observed']} | {row['missed']} | "
                  f"{row['missed_pct']} | {row['extra']} | {row['extra_pct']} |")


if __name__ == "__main__":
    main()
