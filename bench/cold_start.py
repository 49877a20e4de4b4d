"""Cold start benchmark (issue 33): `archlog check` of one configuration as a fresh CI runner
runs it (empty cache), again with nothing changed (warm), and again after a fresh checkout of
the same files (every file's mtime set to now, as a CI runner with a restored cache sees them).

    python bench/cold_start.py WORKSPACE --launch PKG/FILE [--passes cold warm checkout] [--json OUT]

Issue 33 measures navigation2 (ros-navigation/navigation2 main, checked out outside this
repository) with `--launch nav2_bringup/launch/navigation_launch.py`: 12 nodes, 53 C++ files.
Run it niced on a shared machine (`nice -n 10 python bench/cold_start.py ...`); CPU seconds are
the comparable number there, wall seconds only on an idle machine. `checkout` touches the files
of WORKSPACE (their content is left as it is).

Each pass is one child `python -m archlog check` with ARCHLOG_CACHE_DIR set (autoware_bench.py's
run_pass): wall and CPU seconds (user + system of the check and its workers), peak memory, the
translation units in the cache, the findings per rule and the diagnostics per code.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

from autoware_bench import run_pass


def fresh_checkout(workspace: Path) -> None:
    """Every file's mtime set to now: what a new clone of the same commit gives."""
    now = time.time_ns()
    for folder, _dirs, files in os.walk(workspace):
        for name in files:
            path = Path(folder, name)
            if not path.is_symlink():
                os.utime(path, ns=(now, now))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("workspace", type=Path)
    parser.add_argument("--launch", action="append", default=[], help="PKG/FILE, repeatable")
    parser.add_argument("--cache", type=Path, help="cache folder (emptied before a cold pass); default: a temporary one")
    parser.add_argument("--passes", nargs="+", choices=["cold", "warm", "checkout"], default=["cold", "warm", "checkout"])
    parser.add_argument("--json", type=Path, help="also write the results here")
    opts = parser.parse_args()
    workspace = opts.workspace.resolve()
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        cache = opts.cache or Path(tmp) / "cache"
        for index, kind in enumerate(opts.passes, 1):
            if kind == "cold":
                shutil.rmtree(cache, ignore_errors=True)
            elif kind == "checkout":
                fresh_checkout(workspace)
            name = kind if opts.passes.count(kind) == 1 else f"{kind} {index}"
            print(f"{name} pass ...", file=sys.stderr, flush=True)
            results[name] = run_pass(workspace, cache, Path(tmp) / f"{index}.json", tuple(opts.launch))
    print("| pass | TUs | wall s | cpu s | peak MB (process / tree) | nodes | findings | exit |")
    print("|---|---|---|---|---|---|---|---|")
    for name, r in results.items():
        print(f"| {name} | {r['tus']} | {r['wall_s']} | {r['cpu_s']} | {r['peak_process_mb']} / {r['peak_tree_mb']} | "
              f"{r.get('nodes', '-')} | {sum(r.get('findings', {}).values())} | {r['exit']} |")
    print(json.dumps(results, indent=1))
    if opts.json:
        opts.json.write_text(json.dumps({"workspace": str(workspace), "launch": opts.launch, "passes": results},
                                        indent=1) + "\n")


if __name__ == "__main__":
    main()
