"""Benchmark of behavior recovery (issue 9): the share of publish calls whose trigger archlog
recovers (timer, loop, callback or start-up rather than unknown), per system and overall, with
timings. ROSInfer recovers 87%; the target is 90%.

    python bench/behavior_bench.py PATH... [--json FILE] [--warm]

Each PATH is a corpus system variant (a folder with case.json: its launch files and args are
used), a corpus folder (every */*/case.json below it), or a workspace (every node executable
once, as `archlog check PATH` without --launch does).

A publish call is counted once per source location (file:line), over every node instance that
runs it; it is recovered when archlog gives it at least one trigger and none of them is
`unknown`. Twin variants (buggy/clean) of a corpus system count their shared calls once in the
totals. The table also gives the publishers that no publish call uses (publish calls archlog did
not find, or publishers handed to a library), the outputs that require an input, and the
seconds spent: the whole analysis, of which extraction, and the rules (behavior relations and
every shipped rule). Extraction starts from an empty cache unless --warm.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from collections import Counter, defaultdict
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CPP_SUFFIXES = {".cpp", ".cc", ".cxx", ".h", ".hpp", ".hh", ".hxx"}


@dataclass
class SystemResult:
    name: str
    group: str  # twins share a group: their calls are counted once in the totals
    calls: dict[tuple[str, int], set[str]] = field(default_factory=dict)  # (file, line) -> triggers
    publishers: int = 0
    unused_publishers: int = 0
    requiring_outputs: int = 0
    al601: int = 0
    seconds: float = 0.0
    extract_seconds: float = 0.0
    rules_seconds: float = 0.0
    error: str | None = None

    def recovered(self) -> int:
        return sum(1 for triggers in self.calls.values() if _recovered(triggers))


def _recovered(triggers: set[str]) -> bool:
    return bool(triggers) and "unknown" not in triggers


def _language(file: str) -> str:
    return "C++" if Path(file).suffix in CPP_SUFFIXES else "Python"


def systems(paths: list[Path]) -> list[tuple[Path, str, str]]:
    """(path, name, twin group) of every system the arguments name."""
    found = []
    for path in paths:
        path = path.resolve()
        if (path / "case.json").is_file():
            found.append((path, f"{path.parent.parent.name}/{path.parent.name}/{path.name}", str(path.parent)))
        elif cases := sorted(p.parent for p in path.glob("*/*/case.json")):
            found += [(c, f"{path.name}/{c.parent.name}/{c.name}", str(c.parent)) for c in cases]
        elif path.is_dir():
            found.append((path, path.name, str(path)))
        else:
            raise SystemExit(f"not a folder: {path}")
    return found


def measure(path: Path, name: str, group: str) -> SystemResult:
    from archlog.analysis import analyse
    from archlog.rules.engine import Engine
    from archlog.rules.ruleset import load_rules

    result = SystemResult(name, group)
    case = json.loads((path / "case.json").read_text()) if (path / "case.json").is_file() else {}
    start = time.perf_counter()
    try:
        analysis = analyse([path], case.get("launch", []), case.get("args", {}),
                           [path / m for m in case.get("models", [])])
        result.seconds = time.perf_counter() - start
        result.extract_seconds = analysis.timings.get("extract", 0.0)
        clock = time.perf_counter()
        ctl, findings = Engine(load_rules([])).run(analysis.store)
        result.rules_seconds = time.perf_counter() - clock
    except Exception as exc:  # a crash is a result of the benchmark too
        result.seconds = time.perf_counter() - start
        result.error = f"{type(exc).__name__}: {exc}"
        return result
    store = analysis.store
    triggers: dict[str, set[str]] = defaultdict(set)
    for call, trigger, _source in store.rows("publish_trigger"):
        triggers[str(call)].add(str(trigger))
    used = set()
    for call, _node, pub in store.rows("publish_call"):
        used.add(str(pub))
        where = store.location(str(call))
        key = (where[0], where[1]) if where else (str(call), 0)
        result.calls.setdefault(key, set()).update(triggers[str(call)])
    publishers = {str(row[0]) for row in store.rows("publisher")}
    result.publishers = len(publishers)
    result.unused_publishers = len(publishers - used)
    result.requiring_outputs = sum(1 for _ in ctl.symbolic_atoms.by_signature("requires", 2))
    result.al601 = sum(1 for f in findings if f.rule.id == "AL601")
    return result


def share(recovered: int, total: int) -> str:
    return f"{100.0 * recovered / total:5.1f}%" if total else "    -"


def report(results: list[SystemResult]) -> dict:
    header = (f"{'system':48} {'calls':>6} {'known':>6} {'share':>6} {'pubs':>5} {'no call':>7} {'requires':>8} "
              f"{'AL601':>5} {'total s':>8} {'extract':>8} {'rules':>6}")
    print(header)
    for r in results:
        if r.error:
            print(f"{r.name:48} crashed after {r.seconds:.1f} s: {r.error}")
            continue
        print(f"{r.name:48} {len(r.calls):6d} {r.recovered():6d} {share(r.recovered(), len(r.calls)):>6} "
              f"{r.publishers:5d} {r.unused_publishers:7d} {r.requiring_outputs:8d} {r.al601:5d} "
              f"{r.seconds:8.2f} {r.extract_seconds:8.2f} {r.rules_seconds:6.2f}")
    distinct: dict[tuple[str, str, int], set[str]] = {}
    for r in results:
        for (file, line), triggers in r.calls.items():
            distinct.setdefault((r.group, file, line), set()).update(triggers)
    by_language: dict[str, Counter] = defaultdict(Counter)
    kinds: Counter = Counter()
    for (_group, file, _line), triggers in distinct.items():
        counter = by_language[_language(file)]
        counter["calls"] += 1
        counter["recovered"] += _recovered(triggers)
        kinds.update(triggers or {"(none)"})
    total = len(distinct)
    recovered = sum(_recovered(t) for t in distinct.values())
    print(f"\ndistinct publish calls: {total}, trigger recovered: {recovered} ({share(recovered, total).strip()})")
    for language, counter in sorted(by_language.items()):
        print(f"  {language:7} {counter['calls']:5d} calls, {counter['recovered']:5d} recovered "
              f"({share(counter['recovered'], counter['calls']).strip()})")
    print("  triggers over distinct calls: " + ", ".join(f"{k} {n}" for k, n in sorted(kinds.items())))
    seconds = sum(r.seconds + r.rules_seconds for r in results)
    print(f"  {len(results)} systems, {sum(1 for r in results if r.error)} crashed, {seconds:.1f} s "
          f"(analysis {sum(r.seconds for r in results):.1f} s, of which extraction "
          f"{sum(r.extract_seconds for r in results):.1f} s; rules {sum(r.rules_seconds for r in results):.1f} s)")
    return {"systems": [{"name": r.name, "calls": len(r.calls), "recovered": r.recovered(),
                         "publishers": r.publishers, "publishers_without_call": r.unused_publishers,
                         "requiring_outputs": r.requiring_outputs, "al601": r.al601, "seconds": round(r.seconds, 3),
                         "extract_seconds": round(r.extract_seconds, 3), "rules_seconds": round(r.rules_seconds, 3),
                         "error": r.error,
                         "unrecovered": sorted(f"{f}:{line} {sorted(t) or '(none)'}" for (f, line), t in r.calls.items()
                                               if not _recovered(t))} for r in results],
            "distinct_calls": total, "recovered": recovered,
            "by_language": {k: dict(v) for k, v in by_language.items()}, "triggers": dict(kinds)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("paths", nargs="+", type=Path)
    parser.add_argument("--json", type=Path, help="also write the numbers (and the unrecovered calls) as JSON")
    parser.add_argument("--warm", action="store_true", help="keep archlog's extraction cache (default: a fresh one)")
    opts = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="archlog-bench-cache-") as cache:
        if not opts.warm:
            os.environ["ARCHLOG_CACHE_DIR"] = cache
        results = []
        for path, name, group in systems(opts.paths):
            results.append(measure(path, name, group))
            print(f"  measured {name}", file=sys.stderr, flush=True)
        data = report(results)
    if opts.json:
        opts.json.write_text(json.dumps(data, indent=1) + "\n")


if __name__ == "__main__":
    main()
