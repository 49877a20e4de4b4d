"""Benchmark: launch interpretation speed on generated launch trees and on the corpus.

    python bench/launch_bench.py [--elements 1000] [--repeat 7]

Target (issue 3): 1,000 launch elements resolved in under 50 ms.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.ros1 import LaunchInterpreter
from archlog.extract.workspace.index import Workspace

ROOT = Path(__file__).resolve().parent.parent


def generate(folder: Path, elements: int) -> tuple[Path, int]:
    """A main file with robots in groups, each including a sensor file: nodes, remaps, params, args."""
    (folder / "sensors.launch").write_text(
        '<launch>\n  <arg name="prefix"/>\n  <arg name="rate" default="10"/>\n'
        '  <node pkg="demo" type="laser" name="$(arg prefix)_laser">\n'
        '    <remap from="scan" to="$(arg prefix)/scan"/>\n    <param name="rate" value="$(arg rate)"/>\n'
        '  </node>\n  <node pkg="demo" type="imu" name="$(arg prefix)_imu" args="data:=imu/data _hz:=100"/>\n'
        '</launch>\n')
    robot = ('  <group ns="robot{i}" if="$(eval {i} % 7 != 3)">\n    <remap from="odom" to="odometry"/>\n'
             '    <param name="~frame" value="base_{i}"/>\n'
             '    <node pkg="demo" type="driver" name="driver"><remap from="cmd" to="cmd_vel"/>'
             '<rosparam>{{gains: {{p: 1.0, d: 0.1}}}}</rosparam></node>\n'
             '    <include file="$(dirname)/sensors.launch"><arg name="prefix" value="r{i}"/></include>\n'
             '  </group>\n')
    per_robot = 18  # elements per robot block, counting the included file's
    count = max(1, elements // per_robot)
    main = folder / "main.launch"
    main.write_text('<launch>\n  <arg name="sim" default="true"/>\n'
                    + "".join(robot.format(i=i) for i in range(count)) + "</launch>\n")
    return main, count * per_robot


def time_load(files: list[Path], roots: list[Path], repeat: int) -> tuple[float, int]:
    times, nodes = [], 0
    for _ in range(repeat):
        sink = DiagnosticSink()
        workspace = Workspace(roots, sink)
        start = time.perf_counter()
        config = LaunchInterpreter(workspace, sink).load(files, {})
        times.append(time.perf_counter() - start)
        nodes = len(config.nodes)
    return statistics.median(times), nodes


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--elements", type=int, default=1000)
    parser.add_argument("--repeat", type=int, default=7)
    opts = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        main_file, elements = generate(Path(tmp), opts.elements)
        seconds, nodes = time_load([main_file], [Path(tmp), ROOT / "corpus" / "launch" / "_pkgs"], opts.repeat)
    print(f"generated tree: {elements} elements, {nodes} nodes: {seconds * 1000:.1f} ms "
          f"({seconds * 1e6 / elements:.1f} us per element)")
    cases = sorted(p for p in (ROOT / "corpus" / "launch").iterdir() if (p / "main.launch").is_file())
    total = sum(time_load([c / "main.launch"], [c, ROOT / "corpus" / "launch" / "_pkgs"], opts.repeat)[0]
                for c in cases)
    print(f"corpus/launch: {len(cases)} cases in {total * 1000:.1f} ms")


if __name__ == "__main__":
    main()
