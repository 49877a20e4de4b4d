"""Scale benchmark: `archlog check` on generated ROS 1 workspaces of N node instances.

    python bench/scale_bench.py [--sizes 1000 2000 5000] [--naming distinct fleet] [--repeat 1]

Each workspace holds one package of 20 node types described by YAML models (about 5 topics per
node: three outputs, an input remapped in the launch file to a launch argument, an input used by
its plain name; a `~rate` parameter) and a launch tree three includes deep (top -> unit -> sensors
-> drivers), one unit of 20 nodes per `<group ns>`. About 1% of the nodes get a planted near-miss
typo (an argument that swaps two letters of the input's topic) and 0.5% a type mismatch (the
input remapped onto another type's topic). With `--incomplete-share S`, the models of that share of
the node types say they are incomplete (then rules stay quiet where such a node might be the
missing counterpart, and fewer planted defects are reported). Two namings:

- distinct: every unit under its own made-up word (/kotaru/front_lidar/scan), names mostly unique;
- fleet: robots under /robot_K with the same relative names, as real multi-robot systems look.

For each size and naming it prints cpu seconds and peak memory of `archlog check` (a child
process, measured with wait4), the near_name facts, the findings per rule (AL102 must equal the
planted typos), the share of handing facts to clingo and the largest phases (shares of the cpu time of
a run in another child); then the cpu growth exponents (1,000 -> 10,000 and first -> last size).
"""

from __future__ import annotations

import argparse
import cProfile
import json
import math
import os
import pstats
import random
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

import yaml
from rapidfuzz import process
from rapidfuzz.distance import DamerauLevenshtein

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = "scale_nodes"
DEVICES = ["front_lidar", "rear_lidar", "left_camera", "right_camera", "depth_camera", "imu", "gps", "wheel_odometry",
           "base_controller", "arm_controller", "gripper", "battery", "localization", "mapping", "global_planner",
           "local_planner", "obstacle_layer", "teleop", "safety_monitor", "docking"]
STREAMS = [("scan", "points", "health"), ("image_raw", "camera_info", "exposure"), ("data", "temperature", "bias"),
           ("fix", "velocity", "satellites"), ("odom", "twist", "slip"), ("state", "command", "effort"),
           ("pose", "covariance", "residual"), ("plan", "cost", "progress"), ("grid", "updates", "stats")]
SYLLABLES = ["ka", "to", "ru", "mi", "ne", "so", "la", "vi", "de", "po", "fu", "zi", "ge", "ha", "jo", "be", "ty",
             "qua", "sel", "mor", "dan", "wex", "kil", "yon"]
LAYERS = (("unit.launch", 0, 7), ("sensors.launch", 7, 14), ("drivers.launch", 14, 20))


def channel(kind: int, stream: int) -> str:
    return f"{DEVICES[kind]}/{STREAMS[kind % len(STREAMS)][stream]}"


def channel_type(kind: int, stream: int) -> str:
    return f"scale_msgs/{DEVICES[kind].title().replace('_', '')}{STREAMS[kind % len(STREAMS)][stream].title()}"


def inputs(kind: int) -> tuple[tuple[int, int], tuple[int, int]]:
    """The two channels node type `kind` subscribes to: one through a remap, one by its name."""
    return ((kind + 1) % 20, 0), ((kind + 7) % 20, 1)


def models(incomplete: float = 0.0) -> dict:
    """The 20 node types; the first `incomplete` share of them marked incomplete (their ports may
    not all be listed, so every node of theirs might use any name of their ports' types)."""
    result = []
    for kind in range(20):
        (ra, sa), (rb, sb) = inputs(kind)
        result.append({
            "package": PACKAGE, "executable": f"node_{kind}", "name": DEVICES[kind],
            "publishers": [{"name": channel(kind, s), "type": channel_type(kind, s)} for s in range(3)],
            "subscribers": [{"name": "input", "type": channel_type(ra, sa)},
                            {"name": channel(rb, sb), "type": channel_type(rb, sb)}],
            "params": [{"name": "~rate", "default": 10}],
        } | ({"incomplete": "generated as incomplete"} if kind < round(20 * incomplete) else {}))
    return {"models": result}


def namespaces(count: int, naming: str, seed: int) -> list[str]:
    """Fleet: robot_K. Distinct: made-up words at least 3 edits apart, so no two units' topics are
    near misses of each other (only the planted typos are)."""
    if naming == "fleet":
        return [f"robot_{u}" for u in range(count)]
    rng, seen = random.Random(seed), []
    while len(seen) < count:
        word = "".join(rng.choice(SYLLABLES) for _ in range(4))
        if process.extractOne(word, seen, scorer=DamerauLevenshtein.distance, score_cutoff=2) is None:
            seen.append(word)
    return sorted(seen)


def typo(name: str, rng: random.Random) -> str:
    """Swap two neighbouring letters of the last segment (one edit)."""
    head, _, last = name.rpartition("/")
    i = rng.randrange(len(last) - 1)
    while last[i] == last[i + 1] or not (last[i].isalpha() and last[i + 1].isalpha()):
        i = rng.randrange(len(last) - 1)
    return f"{head}/{last[:i]}{last[i + 1]}{last[i]}{last[i + 2:]}"


def generate(root: Path, nodes: int, naming: str, seed: int = 1, incomplete: float = 0.0) -> dict[str, int]:
    """Write the workspace; returns the planted defects."""
    rng = random.Random(seed)
    pkg = root / "src" / PACKAGE
    (pkg / "launch").mkdir(parents=True)
    (pkg / "package.xml").write_text(f'<?xml version="1.0"?>\n<package format="2">\n  <name>{PACKAGE}</name>\n'
                                     '  <version>0.1.0</version>\n  <description>generated</description>\n'
                                     '  <maintainer email="a@b.c">a</maintainer>\n  <license>MIT</license>\n'
                                     '  <buildtool_depend>catkin</buildtool_depend>\n</package>\n')
    (pkg / "CMakeLists.txt").write_text(f"cmake_minimum_required(VERSION 3.0.2)\nproject({PACKAGE})\n"
                                        "find_package(catkin REQUIRED)\ncatkin_package()\n")
    (root / "models.yaml").write_text(yaml.safe_dump(models(incomplete), sort_keys=False))
    for index, (file, first, last) in enumerate(LAYERS):
        lines = ["<launch>", '  <arg name="ns"/>']
        lines += [f'  <arg name="in_{k}" default="{channel(*inputs(k)[0])}"/>' for k in range(first, last)]
        if index == 0:
            lines += [f'  <arg name="in_{k}" default="{channel(*inputs(k)[0])}"/>' for k in range(last, 20)]
            lines.append('  <group ns="$(arg ns)">')
        for k in range(first, last):
            lines += [f'    <node pkg="{PACKAGE}" type="node_{k}" name="{DEVICES[k]}">',
                      f'      <remap from="input" to="$(arg in_{k})"/>',
                      f'      <param name="rate" value="{5 + k}"/>', "    </node>"]
        if index + 1 < len(LAYERS):
            lines.append(f'    <include file="$(find {PACKAGE})/launch/{LAYERS[index + 1][0]}" pass_all_args="true"/>')
        if index == 0:
            lines.append("  </group>")
        lines.append("</launch>")
        (pkg / "launch" / file).write_text("\n".join(lines) + "\n")
    planted = Counter[str]()
    top = ["<launch>"]
    for ns in namespaces(nodes // 20, naming, seed):
        top.append(f'  <include file="$(find {PACKAGE})/launch/unit.launch">')
        top.append(f'    <arg name="ns" value="{ns}"/>')
        for k in range(20):
            roll = rng.random()
            if roll < 0.01:
                top.append(f'    <arg name="in_{k}" value="{typo(channel(*inputs(k)[0]), rng)}"/>')
                planted["typo"] += 1
            elif roll < 0.015:
                top.append(f'    <arg name="in_{k}" value="{channel((k + 2) % 20, 2)}"/>')
                planted["type mismatch"] += 1
        top.append("  </include>")
    top.append("</launch>")
    (pkg / "launch" / "top.launch").write_text("\n".join(top) + "\n")
    return dict(planted)


def check_command(root: Path, out: Path) -> list[str]:
    return [sys.executable, "-m", "archlog", "check", str(root), "--launch", f"{PACKAGE}/launch/top.launch",
            "--model", str(root / "models.yaml"), "--format", "json", "--output", str(out), "--fail-on", "never"]


def measure(root: Path, limit_mb: int) -> tuple[float, float, dict | None]:
    """cpu seconds (user + system) and peak MB of one `archlog check`, and its JSON report (None
    when it failed, e.g. past the memory limit)."""
    out = root / "report.json"

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (limit_mb << 20, limit_mb << 20))

    proc = subprocess.Popen(check_command(root, out), cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            preexec_fn=limit)
    _pid, status, usage = os.wait4(proc.pid, 0)
    report = json.loads(out.read_text()) if status == 0 else None
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, report


def phases(root: Path) -> tuple[dict[str, float], int]:
    """Seconds per phase of an in-process run (analysis stages, then the engine's), and near_name facts."""
    from archlog.analysis import analyse
    from archlog.rules.engine import Engine
    from archlog.rules.ruleset import load_rules

    analysis = analyse([root], [f"{PACKAGE}/launch/top.launch"], {}, [root / "models.yaml"])
    engine = Engine(load_rules([]))
    ctl, _findings = engine.run(analysis.store)
    seconds = {**analysis.timings, **engine.timings}
    near = sum(1 for _ in ctl.symbolic_atoms.by_signature("near_name", 3))
    return seconds, near


def phases_apart(root: Path, top: int) -> tuple[dict[str, float], int]:
    """`phases` in a child process (with a cProfile of TOP functions printed when top > 0), so that
    this process stays small: a check forked from it counts its memory until it execs."""
    done = subprocess.run([sys.executable, __file__, "--phases-of", str(root), "--profile", str(top)], cwd=ROOT,
                          check=True, capture_output=True, text=True)
    *printed, last = done.stdout.splitlines()
    if printed:
        print("\n".join(printed))
    seconds, near = json.loads(last)
    return seconds, near


def print_phases(root: Path, top: int) -> None:
    """The phases in cpu seconds of this process (the stages time themselves with perf_counter,
    which is wall time: on a busy machine that counts other processes' turns)."""
    time.perf_counter = time.process_time
    profiler = cProfile.Profile()
    seconds, near = profiler.runcall(phases, root) if top else phases(root)
    if top:
        pstats.Stats(profiler).sort_stats("cumulative").print_stats(top)
    print(json.dumps([seconds, near]))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 2000, 5000])
    parser.add_argument("--naming", nargs="+", choices=["distinct", "fleet"], default=["distinct", "fleet"])
    parser.add_argument("--repeat", type=int, default=1, help="runs per size (the median is printed)")
    parser.add_argument("--profile", type=int, default=0, metavar="TOP", help="also print a cProfile of each run")
    parser.add_argument("--limit-mb", type=int, default=4096, help="address-space limit of each check")
    parser.add_argument("--incomplete-share", type=float, default=0.0, metavar="SHARE",
                        help="share of the node types whose models are marked incomplete (0.9: 18 of 20)")
    parser.add_argument("--keep", type=Path, help="write the workspaces here instead of a temporary folder")
    parser.add_argument("--phases-of", type=Path, help=argparse.SUPPRESS)
    opts = parser.parse_args()
    if opts.phases_of:
        print_phases(opts.phases_of, opts.profile)
        return
    print("| naming | N | near_name facts | cpu s | peak MB | to-clingo | largest phases | findings | planted |")
    print("|---|---|---|---|---|---|---|---|---|")
    cpu: dict[str, dict[int, float]] = {}
    for naming in opts.naming:
        for size in opts.sizes:
            with tempfile.TemporaryDirectory(dir=opts.keep) as tmp:
                root = Path(tmp) / f"{naming}_{size}"
                planted = generate(root, size, naming, incomplete=opts.incomplete_share)
                runs = [measure(root, opts.limit_mb) for _ in range(opts.repeat)]
                if runs[0][2] is None:
                    print(f"| {naming} | {size:,} | - | failed after {runs[0][0]:.1f} s cpu (limit {opts.limit_mb} MB) "
                          "| | | | | |", flush=True)
                    continue
                seconds = statistics.median(r[0] for r in runs)
                peak = statistics.median(r[1] for r in runs)
                rules = Counter(f["rule"] for f in runs[0][2]["findings"])
                split, near = phases_apart(root, opts.profile)
                total = sum(split.values())
                largest = ", ".join(f"{k} {v / total:.0%}" for k, v in sorted(split.items(), key=lambda kv: -kv[1])[:3])
                cpu.setdefault(naming, {})[size] = seconds
                print(f"| {naming} | {size:,} | {near:,} | {seconds:.1f} | {peak:,.0f} | {split['to-clingo'] / total:.1%} "
                      f"| {largest} | "
                      f"{' '.join(f'{r}:{c}' for r, c in sorted(rules.items()))} | "
                      f"{' '.join(f'{k}:{v}' for k, v in sorted(planted.items()))} |", flush=True)
    for naming, series in cpu.items():
        sizes = sorted(series)
        for first, last in sorted({(sizes[0], 10000), (sizes[0], sizes[-1])}):
            if first < last and last in series:
                exponent = math.log(series[last] / series[first]) / math.log(last / first)
                print(f"growth exponent ({naming}, cpu, {first:,} -> {last:,}): {exponent:.2f}")


if __name__ == "__main__":
    main()
