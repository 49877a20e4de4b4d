"""Generated property-based tests on the corpus/testgen systems (issue 20): examples per second on
each fixed twin, and for each planted defect the median over seeds of the time and the number of
examples (launches of the nodes under test, shrinking included) until the failure is reported.

    python bench/testgen_bench.py [--seeds 5] [--examples 30] [--shrink-seconds 60] [SYSTEM...]

Needs Debian's ROS 1 (roslaunch, rospy) and g++. Prints a Markdown table.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from support.testgen_corpus import prepare, run_generated, systems  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", metavar="SYSTEM", help="corpus/testgen systems (default: all)")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--examples", type=int, default=30, help="examples per run (fixed twins, and the search "
                        "budget on the buggy systems)")
    parser.add_argument("--shrink-seconds", type=int, default=60)
    options = parser.parse_args()
    chosen = [s for s in systems() if not options.names or s.name in options.names]
    print("| system | fixed twin: examples/s | defect found (seeds) | median s to report | median examples "
          "| max messages after shrinking |")
    print("|---|---|---|---|---|---|")
    for system in chosen:
        with tempfile.TemporaryDirectory() as tmp:
            out, _case = prepare(system / "clean", Path(tmp) / "clean")
            clean = run_generated(out, options.examples, seed=0)
            rate = f"{clean.examples / clean.seconds:.2f}" + ("" if clean.passed else " (FAILED)")
            out, _case = prepare(system / "buggy", Path(tmp) / "buggy")
            runs = [run_generated(out, options.examples, seed, options.shrink_seconds) for seed in range(options.seeds)]
        found = [r for r in runs if not r.passed and r.replay is not None]
        seconds = statistics.median(r.seconds for r in found) if found else float("nan")
        examples = statistics.median(r.examples for r in found) if found else float("nan")
        worst = max((r.messages() for r in found), default=0)
        print(f"| {system.name} | {rate} | {len(found)}/{len(runs)} | {seconds:.1f} | {examples:.0f} | {worst} |",
              flush=True)


if __name__ == "__main__":
    main()
