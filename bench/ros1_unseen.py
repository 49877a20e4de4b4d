"""ROS 1 robots nobody tuned archlog on, split into a tune and a held-out part (issue 30).

Each robot is its public repositories checked out side by side under ROOT/ROBOT/ (the robot's own
and its simulator's); bench/results/ros1_unseen.md lists them with their commits. Each launch file
is checked twice: the robot's repositories alone, and with DEPS added to the analysed paths (public
packages the launch files include or run, as a user's machine would have them installed).

The split is fixed by the robot's name alone: a robot is tuned on when sha256(name), read as a
number, is even. Work on archlog looks at the tune part; the held-out part is run once, at the end.

    python bench/ros1_unseen.py ROOT DEPS [--part tune|held-out|all] [--output OUT.json]

Prints one line per run (findings per severity, nodes partial or opaque, parts not read) and each
finding; the JSON holds the findings, the coverage reasons and the parts not read. Whether a
finding is true or false is read by a person (bench/results/ros1_unseen.md).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import subprocess
import sys
from pathlib import Path

LAUNCH = {
    "jackal": ["jackal_gazebo/launch/jackal_world.launch", "jackal_navigation/launch/amcl_demo.launch",
               "jackal_navigation/launch/gmapping_demo.launch", "jackal_control/launch/teleop.launch"],
    "dingo": ["dingo_gazebo/launch/dingo_world.launch", "dingo_navigation/launch/amcl_demo.launch",
              "dingo_navigation/launch/gmapping_demo.launch", "dingo_control/launch/teleop.launch"],
    "ridgeback": ["ridgeback_gazebo/launch/ridgeback_world.launch", "ridgeback_navigation/launch/amcl_demo.launch",
                  "ridgeback_navigation/launch/gmapping_demo.launch", "ridgeback_control/launch/teleop.launch"],
    "warthog": ["warthog_gazebo/launch/warthog_world.launch", "warthog_control/launch/teleop.launch"],
    "turtlebot3": ["turtlebot3_gazebo/launch/turtlebot3_world.launch",
                   "turtlebot3_navigation/launch/turtlebot3_navigation.launch",
                   "turtlebot3_slam/launch/turtlebot3_slam.launch", "turtlebot3_bringup/launch/turtlebot3_robot.launch"],
}


def tuned(robot: str) -> bool:
    """Whether a robot belongs to the tune part (fixed by its name alone)."""
    return int(hashlib.sha256(robot.encode()).hexdigest(), 16) % 2 == 0


def check(paths: list[Path], launch: str) -> dict:
    """One `archlog check` run as a user would make it, its JSON report reduced to what is read."""
    command = [sys.executable, "-m", "archlog", "check", *map(str, paths), "--launch", launch, "--format", "json",
               "--fail-on", "never"]
    result = subprocess.run(command, capture_output=True, text=True, timeout=1800)
    if result.returncode != 0:
        return {"error": result.stderr.strip().splitlines()[-1:]}
    report = json.loads(result.stdout)
    return {
        "summary": report["summary"],
        "findings": [{"rule": f["rule"], "severity": f["severity"], "message": f["message"],
                      "at": f"{f['locations'][0]['file']}:{f['locations'][0]['line']}"} for f in report["findings"]],
        "partial": {n["node"]: [r["message"] for r in n["reasons"]]
                    for n in report["coverage"]["nodes"] if n["status"] != "recovered"},
        "holes": [f"{h['file']}:{h['line']}: {h['message']}" for h in report["coverage"].get("holes", [])],
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", type=Path)
    parser.add_argument("deps", type=Path)
    parser.add_argument("--part", choices=("tune", "held-out", "all"), default="tune")
    parser.add_argument("--output", type=Path)
    args = parser.parse_args()
    runs = []
    for robot, launches in LAUNCH.items():
        part = "tune" if tuned(robot) else "held-out"
        if args.part not in (part, "all"):
            continue
        for launch in launches:
            for label, paths in (("alone", [args.root / robot]), ("with deps", [args.root / robot, args.deps])):
                run = {"robot": robot, "part": part, "launch": launch, "paths": label, **check(paths, launch)}
                runs.append(run)
                summary = run.get("summary") or {}
                print(f"{part:8} {robot:10} {launch:55} {label:9} errors {summary.get('error', '-')} warnings "
                      f"{summary.get('warning', '-')} notes {summary.get('note', '-')} partial/opaque "
                      f"{len(run.get('partial', {}))} unread {len(run.get('holes', []))} {run.get('error', '')}")
                for finding in run.get("findings", []):
                    print(f"    {finding['severity']:7} {finding['rule']} {finding['at']}: {finding['message']}")
    if args.output:
        args.output.write_text(json.dumps(runs, indent=1) + "\n")


if __name__ == "__main__":
    main()
