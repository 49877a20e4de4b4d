"""Generated property-based tests on the corpus/testgen systems (issue 20): examples per second on
each fixed twin, and for each planted defect the median over seeds of the time and the number of
examples (launches of the nodes under test, shrinking included) until the failure is reported.

    python bench/testgen_bench.py [--seeds 5] [--examples 30] [--shrink-seconds 60] [SYSTEM...]
    python bench/testgen_bench.py --debian N [--debsrc /work/debsrc]
    python bench/testgen_bench.py --ros2 N   # the corpus/ros2 clean twins and corpus/testgen_ros2 on rclpy
    python bench/testgen_bench.py --oracle N CHECKOUT...   # the rclpy oracle's programs, N examples each

The last line of the corpus table is the soundness summary (issue 32): false failures on the fixed
twins (must be 0), defects found, and the most messages a shrunk failure sends (at most 3).

Needs Debian's ROS 1 (roslaunch, rospy) and g++. Prints a Markdown table. With --debian, runs the
generated test of Debian's robot_state_publisher and joint_state_publisher (their source packages
in --debsrc, the launch files of bench/debian_nodes) for N examples each: a failure there is a
false failure of the generator. With --oracle, every program of the CHECKOUTs (ament_python packages,
as bench/rclpy_oracle.py finds them) that the oracle observed running (bench/results/rclpy_oracle.json)
gets the generated test of a one-node configuration of it, as the oracle analyses it: a failure there
is a false failure too (a program without an open input, output nor service has nothing to test).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from rclpy_oracle import Program, programs  # noqa: E402
from support.ros2_nodes import private_domain  # noqa: E402
from support.testgen_corpus import Outcome, prepare, run_generated, systems  # noqa: E402
from test_testgen_ros2 import ACTION, CASES, LIFECYCLE, SERVICE, run_case  # noqa: E402

DEBIAN = {"robot_state_publisher": "ros-robot-state-publisher-*", "joint_state_publisher": "ros-joint-state-publisher-*"}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", metavar="SYSTEM", help="corpus/testgen systems (default: all)")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--examples", type=int, default=30, help="examples per run (fixed twins, and the search "
                        "budget on the buggy systems)")
    parser.add_argument("--shrink-seconds", type=int, default=60)
    parser.add_argument("--debian", type=int, metavar="N", help="examples of each Debian node instead")
    parser.add_argument("--debsrc", type=Path, default=Path("/work/debsrc"))
    parser.add_argument("--ros2", type=int, metavar="N", help="examples of each corpus/ros2 clean twin instead")
    parser.add_argument("--oracle", type=int, metavar="N", help="examples of each program of the rclpy oracle "
                        "in the checkouts given as SYSTEMs instead")
    options = parser.parse_args()
    domain = min(private_domain(), 232)  # ROS 2 tests: a private domain in ARCHLOG_TEST_ROS_DOMAINS
    os.environ.setdefault("ARCHLOG_TESTGEN_DOMAINS", f"{domain}-{domain}")
    if options.oracle:
        oracle(options.oracle, [Path(n) for n in options.names])
        return
    if options.debian:
        debian(options.debian, options.debsrc)
        return
    if options.ros2:
        ros2(options.ros2)
        return
    false_failures, found_all, worst_all = 0, 0, 0
    chosen = [s for s in systems() if not options.names or s.name in options.names]
    print("| system | fixed twin: examples/s | defect found (seeds) | median s to report | median examples "
          "| max messages after shrinking | fixed twin: lines run |")
    print("|---|---|---|---|---|---|---|")
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
        print(f"| {system.name} | {rate} | {len(found)}/{len(runs)} | {seconds:.1f} | {examples:.0f} | {worst} "
              f"| {clean.lines()} |", flush=True)
        false_failures += not clean.passed
        found_all += len(found) == len(runs)
        worst_all = max(worst_all, worst)
    print(f"\nsoundness: {false_failures} false failure(s) on {len(chosen)} fixed twins; defect found on every seed in "
          f"{found_all}/{len(chosen)} systems; at most {worst_all} message(s) after shrinking")


def ros2(examples: int) -> None:
    """The generated test of each corpus/ros2 clean twin (as tests/test_testgen_ros2.py picks them)."""
    print("| system | nodes | outcome | examples/s |")
    print("|---|---|---|---|")
    for system, nodes, _expected in CASES:
        with tempfile.TemporaryDirectory() as tmp:
            result, seconds = run_case(system, nodes, Path(tmp), examples)
            reasons = [json.loads(r.read_text())["reason"] for r in Path(tmp).glob("replay/*.json")]
        outcome = "passed" if result.returncode == 0 else "skipped" if result.returncode == 5 else "FAILED"
        rate = f"{examples / seconds:.2f}" if outcome == "passed" else "-"
        print(f"| {system} | {' '.join(nodes) or 'all'} | {outcome} | {rate} |", flush=True)
        if outcome == "FAILED":
            print(f"reason: {'; '.join(reasons) or '-'}\n{result.stdout[-3000:]}")
    with tempfile.TemporaryDirectory() as tmp:
        out, _case = prepare(LIFECYCLE, Path(tmp))
        lifecycle = run_generated(out, examples, seed=0)
    rate = f"{lifecycle.examples / lifecycle.seconds:.2f}" if lifecycle.passed else "-"
    print(f"| testgen_ros2/{LIFECYCLE.parent.name} | all | {'passed' if lifecycle.passed else 'FAILED'} | {rate} |")
    ros2_twins(examples, 3, 15)


def ros2_twins(examples: int, seeds: int, shrink_seconds: int) -> None:
    """corpus/testgen_ros2's twins (a service, an action): the fixed twin for `examples` examples, the
    defect's search on each seed."""
    print("\n| system | fixed twin: examples/s | defect found (seeds) | median s to report | median examples "
          "| max calls or goals after shrinking | reason | fixed twin: lines run |\n|---|---|---|---|---|---|---|---|")
    for system in (SERVICE, ACTION):
        with tempfile.TemporaryDirectory() as tmp:
            out, _case = prepare(system / "clean", Path(tmp) / "clean")
            clean = run_generated(out, examples, seed=0)
            out, _case = prepare(system / "buggy", Path(tmp) / "buggy")
            runs = [run_generated(out, examples, seed, shrink_seconds) for seed in range(seeds)]
        found = [r for r in runs if not r.passed and r.replay is not None]
        rate = f"{clean.examples / clean.seconds:.2f}" + ("" if clean.passed else " (FAILED)")
        reasons = sorted({r.replay["reason"].split(" (")[0] for r in found if r.replay})
        print(f"| {system.name} | {rate} | {len(found)}/{len(runs)} "
              f"| {statistics.median(r.seconds for r in found) if found else float('nan'):.1f} "
              f"| {statistics.median(r.examples for r in found) if found else float('nan'):.0f} "
              f"| {max((r.messages() for r in found), default=0)} | {'; '.join(reasons)} | {clean.lines()} |", flush=True)
        if not clean.passed:
            print(clean.output[-3000:])


def oracle(examples: int, checkouts: list[Path]) -> None:
    """The generated test of each program of the rclpy oracle that the oracle observed running."""
    results = json.loads((ROOT / "bench" / "results" / "rclpy_oracle.json").read_text())["programs"]
    observed = {r["program"] for r in results if r["observed"]}
    chosen = [p for p in programs(checkouts) if f"{p.package}/{p.executable}" in observed]
    print("| program | open ports | examples | outcome | examples/s | lines run |\n|---|---|---|---|---|---|")
    failures = 0
    for program in chosen:
        with tempfile.TemporaryDirectory() as tmp:
            outcome, what = _oracle_program(program, Path(tmp), examples)
        failures += outcome is not None and not outcome.passed
        verdict = "nothing to test" if outcome is None else "passed" if outcome.passed else "FAILED"
        rate = f"{outcome.examples / outcome.seconds:.2f}" if outcome is not None else "-"
        print(f"| {program.package}/{program.executable} | {what} | {outcome.examples if outcome else 0} | {verdict} "
              f"| {rate} | {outcome.lines() if outcome else '-'} |", flush=True)
        if outcome is not None and not outcome.passed:
            at = outcome.output.find("property failed:")  # the report: the steps, then the nodes' output
            print(f"reason: {outcome.replay['reason'] if outcome.replay else '-'}\n{outcome.output[at:at + 3000]}")
    print(f"\nsoundness: {failures} false failure(s) on {len(chosen)} programs")


def _oracle_program(program: Program, tmp: Path, examples: int) -> tuple[Outcome | None, str]:
    """Generate and run the test of a one-node configuration of the program (None: nothing to test)."""
    launch = tmp / f"{program.package}__{program.executable}.launch.xml"
    launch.write_text(f'<launch><node pkg="{program.package}" exec="{program.executable}"/></launch>\n')
    out = tmp / "generated"
    done = subprocess.run([sys.executable, "-m", "archlog", "testgen", str(program.folder), "--launch", str(launch),
                           "--output", str(out)], capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, ROS_DISTRO="kilted"))
    summary = done.stdout.strip().splitlines()[-1].split(";")[0] if done.returncode == 0 else done.stderr.strip()[-120:]
    if done.returncode != 0:
        return None, summary.replace("|", "/").replace("\n", " ")
    return run_generated(out, examples, seed=0, timeout=3600), summary


def debian(examples: int, debsrc: Path) -> None:
    print("| node | examples | passed | examples/s | lines run |")
    print("|---|---|---|---|---|")
    for node, source in DEBIAN.items():
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp)
            package = next(p for p in debsrc.glob(source) if p.is_dir())
            subprocess.run([sys.executable, "-m", "archlog", "testgen", str(package), "--launch",
                            str(ROOT / "bench" / "debian_nodes" / f"{node}.launch"), "--output", str(out)],
                           check=True, capture_output=True)
            outcome = run_generated(out, examples, seed=0, timeout=3600)
        print(f"| {node} | {outcome.examples} | {outcome.passed} | {outcome.examples / outcome.seconds:.2f} "
              f"| {outcome.lines()} |", flush=True)
        if not outcome.passed:
            print(outcome.output[-3000:])


if __name__ == "__main__":
    main()
