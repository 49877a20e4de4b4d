"""Benchmark: extraction and rule evaluation on every corpus system, and near-miss names at scale.

    python bench/run.py [--repeat N]

Prints a table of median seconds per stage and writes bench/results/latest.json.
"""

from __future__ import annotations

import argparse
import json
import random
import statistics
import string
import time
from pathlib import Path

from archlog.analysis import analyse
from archlog.facts.similarity import near_pairs
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules

ROOT = Path(__file__).resolve().parent.parent
STAGES = ("workspace", "launch", "extract", "facts", "rules")


def corpus_run(variant: Path) -> dict[str, float]:
    case = json.loads((variant / "case.json").read_text())
    analysis = analyse([variant], case["launch"], case.get("args", {}), [])
    start = time.perf_counter()
    Engine(load_rules([])).run(analysis.store)
    return {**analysis.timings, "rules": time.perf_counter() - start,
            "facts_count": sum(len(analysis.store.rows(r)) for r in ("publisher", "subscriber", "node"))}


def topic_names(count: int, seed: int = 7) -> list[str]:
    """Realistic names: robots x sensors x streams, with some typos."""
    rng = random.Random(seed)
    robots = [f"robot{i}" for i in range(1, 41)]
    devices = ["front_camera", "rear_camera", "left_lidar", "right_lidar", "imu", "gps", "base", "arm",
               "gripper", "nav", "localization", "planner", "controller", "battery", "depth_camera"]
    streams = ["image_raw", "image_rect_color", "camera_info", "points", "scan", "data", "odom", "cmd_vel",
               "status", "diagnostics", "goal", "feedback", "result", "pose", "joint_states", "twist", "map"]
    names: set[str] = set()
    while len(names) < count:
        name = f"/{rng.choice(robots)}/{rng.choice(devices)}/{rng.choice(streams)}"
        if rng.random() < 0.05:
            i = rng.randrange(1, len(name))
            name = name[:i] + rng.choice(string.ascii_lowercase) + name[i + 1:]
        names.add(name)
    return sorted(names)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=3)
    opts = parser.parse_args()
    results: dict[str, dict] = {}
    variants = sorted(p.parent for corpus in ("ros1", "ros2") for p in (ROOT / "corpus" / corpus).glob("*/*/case.json"))
    print(f"{'system':42} " + " ".join(f"{s:>9}" for s in STAGES) + f" {'total':>8}")
    for variant in variants:
        runs = [corpus_run(variant) for _ in range(opts.repeat)]
        med = {s: statistics.median(r[s] for r in runs) for s in STAGES}
        name = f"{variant.parent.name}/{variant.name}"
        results[name] = med
        print(f"{name:42} " + " ".join(f"{med[s]:9.3f}" for s in STAGES) + f" {sum(med.values()):8.3f}")
    totals = {s: sum(r[s] for r in results.values()) for s in STAGES}
    print(f"{'corpus total':42} " + " ".join(f"{totals[s]:9.3f}" for s in STAGES) + f" {sum(totals.values()):8.3f}")
    for count in (1000, 5000):
        names = topic_names(count)
        times = []
        for _ in range(opts.repeat):
            start = time.perf_counter()
            pairs = near_pairs(names)
            times.append(time.perf_counter() - start)
        results[f"near_miss_{count}"] = {"seconds": statistics.median(times), "pairs": len(pairs)}
        print(f"near-miss join over {count} names: {statistics.median(times):.3f} s ({len(pairs)} pairs)")
    out = ROOT / "bench" / "results"
    out.mkdir(exist_ok=True)
    (out / "latest.json").write_text(json.dumps(results, indent=1) + "\n")


if __name__ == "__main__":
    main()
