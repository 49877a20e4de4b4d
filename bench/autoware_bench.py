"""Real-workspace benchmark: `archlog check` on a whole ROS 1 tree in its rosrun configuration
(no launch file: every executable the workspace declares is one instance), cold and warm.

    python bench/autoware_bench.py WORKSPACE [--cache DIR] [--passes cold warm] [--json OUT]

Issue 18 measures the Autoware.AI 1.10.0 tree: the `[Release] 1.10.0 (#1898)` merge,
commit 9fae6cc7cb8253586578dbb62a2f075b52849e6e of autowarefoundation/autoware, checked out
outside this repository (e.g. `git --work-tree=/work/autoware-src checkout 9fae6cc7 -- .` in a
clone) and passed as `/work/autoware-src/ros/src`. Run it niced on a shared machine
(`nice -n 10 python bench/autoware_bench.py ...`).

Each pass is one `python -m archlog check WORKSPACE --format json` in a child process with
ARCHLOG_CACHE_DIR pointed at the cache folder: `cold` first empties it (default: a fresh
temporary folder), `warm` runs again with nothing changed. For each pass it prints the wall and
cpu seconds (user + system of the check and its extraction workers, from wait4), the peak
resident memory of the largest single process (wait4's maxrss) and of the whole process tree
(sampled every 0.2 s), the translation units (C++ files parsed, one cached result each) and the
seconds per TU, the executables extracted by language, the findings per rule and the diagnostics
per code. While a pass runs, a progress line (TUs cached so far) goes to stderr every 30 s.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import sqlite3
import subprocess
import sys
import tempfile
import threading
import time
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def tree_rss(pid: int) -> int:
    """Resident bytes of a process and all its descendants (0 once it is gone)."""
    total, todo = 0, [pid]
    while todo:
        current = todo.pop()
        try:
            status = Path(f"/proc/{current}/status").read_text()
            children = Path(f"/proc/{current}/task/{current}/children").read_text().split()
        except OSError:
            continue
        total += next((int(line.split()[1]) << 10 for line in status.splitlines() if line.startswith("VmRSS:")), 0)
        todo += map(int, children)
    return total


def cached_tus(cache: Path) -> int:
    """C++ files whose extraction result is in the cache."""
    try:
        with sqlite3.connect(cache / "cpp.sqlite", timeout=30) as db:
            return int(db.execute("SELECT count(*) FROM results").fetchone()[0])
    except sqlite3.Error:
        return 0


class Sampler(threading.Thread):
    """Peak resident memory of a process tree, and a progress line every `every` seconds."""

    def __init__(self, pid: int, cache: Path, every: float = 30.0) -> None:
        super().__init__(daemon=True)
        self.pid, self.cache, self.every = pid, cache, every
        self.peak = 0
        self.done = threading.Event()

    def run(self) -> None:
        start = last = time.monotonic()
        while not self.done.wait(0.2):
            self.peak = max(self.peak, tree_rss(self.pid))
            if time.monotonic() - last >= self.every:
                last = time.monotonic()
                print(f"  {last - start:7.0f} s: {cached_tus(self.cache)} TUs cached, tree {self.peak >> 20} MB peak",
                      file=sys.stderr, flush=True)


def run_pass(workspace: Path, cache: Path, out: Path, launches: tuple[str, ...] = ()) -> dict:
    """One `archlog check` of the rosrun configuration (or of the `launches`) with the cache in `cache`."""
    command = [sys.executable, "-m", "archlog", "check", str(workspace), "--format", "json", "--output", str(out),
               "--fail-on", "never", "--quiet", *(a for launch in launches for a in ("--launch", launch))]
    env = {**os.environ, "ARCHLOG_CACHE_DIR": str(cache)}
    start = time.monotonic()
    proc = subprocess.Popen(command, cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    sampler = Sampler(proc.pid, cache)
    sampler.start()
    stderr = proc.stderr.read() if proc.stderr else b""
    _pid, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    sampler.done.set()
    sampler.join()
    result = {"wall_s": round(wall, 1), "cpu_s": round(usage.ru_utime + usage.ru_stime, 1),
              "peak_process_mb": round(usage.ru_maxrss / 1024), "peak_tree_mb": round(sampler.peak / (1 << 20)),
              "tus": cached_tus(cache), "exit": os.waitstatus_to_exitcode(status)}
    if not out.is_file():
        result["error"] = stderr.decode(errors="replace")[-2000:]
        return result
    report = json.loads(out.read_text())
    origins = Counter(n["origin"] or "opaque" for n in report["coverage"]["nodes"])
    result.update({
        "nodes": len(report["coverage"]["nodes"]), "nodes_by_origin": dict(sorted(origins.items())),
        "recovered": report["coverage"]["recovered"], "partial": report["coverage"]["partial"],
        "opaque": report["coverage"]["opaque"],
        "findings": dict(sorted(Counter(f["rule"] for f in report["findings"]).items())),
        "diagnostics": dict(sorted(Counter(d["code"] for d in report["diagnostics"]).items())),
    })
    return result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("workspace", type=Path)
    parser.add_argument("--cache", type=Path, help="cache folder (emptied before a cold pass); default: a temporary one")
    parser.add_argument("--passes", nargs="+", choices=["cold", "warm"], default=["cold", "warm"],
                        help="in order, e.g. cold warm warm warm")
    parser.add_argument("--reports", type=Path, help="keep each pass's JSON report here as PASS.json")
    parser.add_argument("--json", type=Path, help="also write the results here")
    opts = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        cache = opts.cache or Path(tmp) / "cache"
        reports = opts.reports or Path(tmp)
        reports.mkdir(parents=True, exist_ok=True)
        results = {}
        for index, kind in enumerate(opts.passes, 1):
            if kind == "cold":
                shutil.rmtree(cache, ignore_errors=True)
            name = kind if opts.passes.count(kind) == 1 else f"{kind} {index}"
            print(f"{name} pass ...", file=sys.stderr, flush=True)
            results[name] = run_pass(opts.workspace.resolve(), cache, reports / f"{name.replace(' ', '')}.json")
    print("| pass | TUs | wall s | cpu s | wall s/TU | cpu s/TU | peak MB (process / tree) | nodes | exit |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, r in results.items():
        tus = max(r["tus"], 1)
        print(f"| {name} | {r['tus']} | {r['wall_s']} | {r['cpu_s']} | {r['wall_s'] / tus:.2f} | "
              f"{r['cpu_s'] / tus:.2f} | {r['peak_process_mb']} / {r['peak_tree_mb']} | {r.get('nodes', '-')} | "
              f"{r['exit']} |")
    print(json.dumps(results, indent=1))
    if opts.json:
        opts.json.write_text(json.dumps({"workspace": str(opts.workspace), "passes": results}, indent=1) + "\n")


if __name__ == "__main__":
    main()
