"""Scale benchmark: `archlog check` on generated ROS 1 workspaces of N node instances.

    python bench/scale_bench.py [--sizes 1000 2000 5000] [--naming distinct fleet] [--shape plain infra ros2]
                                [--repeat 1]

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

Three shapes:

- plain: the ports above only;
- infra: as real ROS 1 nodes, every node also has the dangling infrastructure of
  dynamic_reconfigure (publishers `~parameter_descriptions` and `~parameter_updates`, the service
  `~set_parameters`), a `~status` publisher and a `/diagnostics` publisher, those two named by
  private parameters with defaults (`~status_topic`, `~diagnostics_topic`; the launch files set
  `status_topic` of every fifth node type); one node type per unit subscribes to `/diagnostics` and
  to one status topic, the rest have no subscriber;
- ros2: the same system as ROS 2 launch files (XML) and ROS 2 node models, every node with the
  status and diagnostics publishers and the built-in ports of an rclcpp/rclpy node: publishers
  `/rosout` and `/parameter_events` and the six parameter services (`~/describe_parameters`, ...).
  archlog does not add built-in ports itself, so the models list them as ordinary ports.

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
LAYERS = (("unit", 0, 7), ("sensors", 7, 14), ("drivers", 14, 20))
SHAPES = ("plain", "infra", "ros2")
STATUS_SET = range(0, 20, 5)  # node types whose launch file sets ~status_topic
WATCHER = 18  # safety_monitor: subscribes to /diagnostics and to the status topic of node type 0
PARAMETER_SERVICES = ("describe_parameters", "get_parameter_types", "get_parameters", "list_parameters",
                      "set_parameters", "set_parameters_atomically")


def channel(kind: int, stream: int) -> str:
    return f"{DEVICES[kind]}/{STREAMS[kind % len(STREAMS)][stream]}"


def channel_type(kind: int, stream: int) -> str:
    return f"scale_msgs/{DEVICES[kind].title().replace('_', '')}{STREAMS[kind % len(STREAMS)][stream].title()}"


def camel(word: str) -> str:
    return word.title().replace("_", "")


def launch_file(layer: str, shape: str) -> str:
    return f"{layer}.launch.xml" if shape == "ros2" else f"{layer}.launch"


def top_launch(shape: str = "plain") -> str:
    return f"{PACKAGE}/launch/{launch_file('top', shape)}"


def inputs(kind: int) -> tuple[tuple[int, int], tuple[int, int]]:
    """The two channels node type `kind` subscribes to: one through a remap, one by its name."""
    return ((kind + 1) % 20, 0), ((kind + 7) % 20, 1)


def models(incomplete: float = 0.0, shape: str = "plain") -> dict:
    """The 20 node types; the first `incomplete` share of them marked incomplete (their ports may
    not all be listed, so every node of theirs might use any name of their ports' types)."""
    ros2 = shape == "ros2"

    def msg(type_: str) -> str:
        return type_.replace("/", "/msg/", 1) if ros2 else type_

    private, param = ("~/", "") if ros2 else ("~", "~")
    result = []
    for kind in range(20):
        (ra, sa), (rb, sb) = inputs(kind)
        model = {
            "package": PACKAGE, "executable": f"node_{kind}", "name": DEVICES[kind],
            "publishers": [{"name": channel(kind, s), "type": msg(channel_type(kind, s))} for s in range(3)],
            "subscribers": [{"name": "input", "type": msg(channel_type(ra, sa))},
                            {"name": channel(rb, sb), "type": msg(channel_type(rb, sb))}],
            "services": [],
            "params": [{"name": f"{param}rate", "default": 10}],
        }
        if shape != "plain":
            model["publishers"] += [
                {"name": {"param": f"{param}status_topic", "default": f"{private}status"},
                 "type": msg("diagnostic_msgs/DiagnosticStatus")},
                {"name": {"param": f"{param}diagnostics_topic", "default": "/diagnostics"},
                 "type": msg("diagnostic_msgs/DiagnosticArray")}]
            model["params"] += [{"name": f"{param}status_topic", "default": f"{private}status"},
                                {"name": f"{param}diagnostics_topic", "default": "/diagnostics"}]
        if shape != "plain" and kind == WATCHER:
            model["subscribers"] += [{"name": "/diagnostics", "type": msg("diagnostic_msgs/DiagnosticArray")},
                                     {"name": f"status/{DEVICES[0]}", "type": msg("diagnostic_msgs/DiagnosticStatus")}]
        if shape == "infra":
            model["publishers"] += [{"name": "~parameter_descriptions", "type": "dynamic_reconfigure/ConfigDescription"},
                                    {"name": "~parameter_updates", "type": "dynamic_reconfigure/Config"}]
            model["services"] += [{"name": "~set_parameters", "type": "dynamic_reconfigure/Reconfigure"}]
        if ros2:
            model["publishers"] += [{"name": "/rosout", "type": "rcl_interfaces/msg/Log"},
                                    {"name": "/parameter_events", "type": "rcl_interfaces/msg/ParameterEvent"}]
            model["services"] += [{"name": f"~/{service}", "type": f"rcl_interfaces/srv/{camel(service)}"}
                                  for service in PARAMETER_SERVICES]
        if kind < round(20 * incomplete):
            model["incomplete"] = "generated as incomplete"
        result.append(model)
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


def generate(root: Path, nodes: int, naming: str, seed: int = 1, incomplete: float = 0.0,
             shape: str = "plain") -> dict[str, int]:
    """Write the workspace; returns the planted defects."""
    rng = random.Random(seed)
    pkg = root / "src" / PACKAGE
    (pkg / "launch").mkdir(parents=True)
    ros2 = shape == "ros2"
    build = "ament_cmake" if ros2 else "catkin"
    (pkg / "package.xml").write_text(f'<?xml version="1.0"?>\n<package format="{3 if ros2 else 2}">\n'
                                     f'  <name>{PACKAGE}</name>\n'
                                     '  <version>0.1.0</version>\n  <description>generated</description>\n'
                                     '  <maintainer email="a@b.c">a</maintainer>\n  <license>MIT</license>\n'
                                     f'  <buildtool_depend>{build}</buildtool_depend>\n'
                                     f'  <export><build_type>{build}</build_type></export>\n</package>\n')
    (pkg / "CMakeLists.txt").write_text(f"cmake_minimum_required(VERSION 3.5)\nproject({PACKAGE})\n" +
                                        ("find_package(ament_cmake REQUIRED)\nament_package()\n" if ros2 else
                                         "find_package(catkin REQUIRED)\ncatkin_package()\n"))
    (root / "models.yaml").write_text(yaml.safe_dump(models(incomplete, shape), sort_keys=False))
    for index, (layer, first, last) in enumerate(LAYERS):
        (pkg / "launch" / launch_file(layer, shape)).write_text(layer_launch(index, first, last, shape))
    planted = Counter[str]()
    top = ["<launch>"]
    for ns in namespaces(nodes // 20, naming, seed):
        if ros2:  # a ROS 2 include's arguments outlive it, unless a group scopes them
            top.append("  <group>")
        top.append(f'  <include file="$(find{"-pkg-share" if ros2 else ""} {PACKAGE})/launch/{launch_file("unit", shape)}">')
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
        if ros2:
            top.append("  </group>")
    top.append("</launch>")
    (pkg / "launch" / launch_file("top", shape)).write_text("\n".join(top) + "\n")
    return dict(planted)


def layer_launch(index: int, first: int, last: int, shape: str) -> str:
    """One launch file of the tree: its node types' nodes (in the unit's namespace), then the next layer."""
    ros2 = shape == "ros2"
    arg, find, value = ("var", "find-pkg-share", "exec") if ros2 else ("arg", "find", "type")
    declared = range(first, 20 if index == 0 else last)
    lines = ["<launch>", '  <arg name="ns"/>']
    lines += [f'  <arg name="in_{k}" default="{channel(*inputs(k)[0])}"/>' for k in declared]
    if index == 0:
        lines += ["  <group>", '    <push-ros-namespace namespace="$(var ns)"/>'] if ros2 else \
            ['  <group ns="$(arg ns)">']
    for k in range(first, last):
        lines += [f'    <node pkg="{PACKAGE}" {value}="node_{k}" name="{DEVICES[k]}">',
                  f'      <remap from="input" to="$({arg} in_{k})"/>',
                  f'      <param name="rate" value="{5 + k}"/>']
        if shape != "plain" and k in STATUS_SET:
            lines.append(f'      <param name="status_topic" value="status/{DEVICES[k]}"/>')
        lines.append("    </node>")
    if index + 1 < len(LAYERS):
        passed = "" if ros2 else ' pass_all_args="true"'
        lines.append(f'    <include file="$({find} {PACKAGE})/launch/{launch_file(LAYERS[index + 1][0], shape)}"{passed}/>')
    if index == 0:
        lines.append("  </group>")
    lines.append("</launch>")
    return "\n".join(lines) + "\n"


def check_command(root: Path, out: Path, shape: str) -> list[str]:
    return [sys.executable, "-m", "archlog", "check", str(root), "--launch", top_launch(shape),
            "--model", str(root / "models.yaml"), "--format", "json", "--output", str(out), "--fail-on", "never"]


def measure(root: Path, shape: str, limit_mb: int) -> tuple[float, float, dict | None]:
    """cpu seconds (user + system) and peak MB of one `archlog check`, and its JSON report (None
    when it failed, e.g. past the memory limit)."""
    out = root / "report.json"

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (limit_mb << 20, limit_mb << 20))

    proc = subprocess.Popen(check_command(root, out, shape), cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            preexec_fn=limit)
    _pid, status, usage = os.wait4(proc.pid, 0)
    report = json.loads(out.read_text()) if status == 0 else None
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, report


def phases(root: Path, shape: str) -> tuple[dict[str, float], int]:
    """Seconds per phase of an in-process run (analysis stages, then the engine's), and near_name facts."""
    from archlog.analysis import analyse
    from archlog.rules.engine import Engine
    from archlog.rules.ruleset import load_rules

    analysis = analyse([root], [top_launch(shape)], {}, [root / "models.yaml"])
    engine = Engine(load_rules([]))
    ctl, _findings = engine.run(analysis.store)
    seconds = {**analysis.timings, **engine.timings}
    near = sum(1 for _ in ctl.symbolic_atoms.by_signature("near_name", 3))
    return seconds, near


def phases_apart(root: Path, shape: str, top: int) -> tuple[dict[str, float], int]:
    """`phases` in a child process (with a cProfile of TOP functions printed when top > 0), so that
    this process stays small: a check forked from it counts its memory until it execs."""
    done = subprocess.run([sys.executable, __file__, "--phases-of", str(root), "--shape", shape,
                           "--profile", str(top)], cwd=ROOT,
                          check=True, capture_output=True, text=True)
    *printed, last = done.stdout.splitlines()
    if printed:
        print("\n".join(printed))
    seconds, near = json.loads(last)
    return seconds, near


def print_phases(root: Path, shape: str, top: int) -> None:
    """The phases in cpu seconds of this process (the stages time themselves with perf_counter,
    which is wall time: on a busy machine that counts other processes' turns)."""
    time.perf_counter = time.process_time
    profiler = cProfile.Profile()
    seconds, near = profiler.runcall(phases, root, shape) if top else phases(root, shape)
    if top:
        pstats.Stats(profiler).sort_stats("cumulative").print_stats(top)
    print(json.dumps([seconds, near]))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 2000, 5000])
    parser.add_argument("--naming", nargs="+", choices=["distinct", "fleet"], default=["distinct", "fleet"])
    parser.add_argument("--shape", nargs="+", choices=SHAPES, default=["plain"])
    parser.add_argument("--repeat", type=int, default=1, help="runs per size (the median is printed)")
    parser.add_argument("--profile", type=int, default=0, metavar="TOP", help="also print a cProfile of each run")
    parser.add_argument("--limit-mb", type=int, default=4096, help="address-space limit of each check")
    parser.add_argument("--incomplete-share", type=float, default=0.0, metavar="SHARE",
                        help="share of the node types whose models are marked incomplete (0.9: 18 of 20)")
    parser.add_argument("--keep", type=Path, help="write the workspaces here instead of a temporary folder")
    parser.add_argument("--phases-of", type=Path, help=argparse.SUPPRESS)
    opts = parser.parse_args()
    if opts.phases_of:
        print_phases(opts.phases_of, opts.shape[0], opts.profile)
        return
    print("| shape | naming | N | near_name facts | cpu s | peak MB | near-miss | to-clingo | largest phases "
          "| findings | planted |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    cpu: dict[tuple[str, str], dict[int, float]] = {}
    for shape in opts.shape:
        for naming in opts.naming:
            for size in opts.sizes:
                with tempfile.TemporaryDirectory(dir=opts.keep) as tmp:
                    root = Path(tmp) / f"{shape}_{naming}_{size}"
                    planted = generate(root, size, naming, incomplete=opts.incomplete_share, shape=shape)
                    seconds, cells = run(root, shape, opts)
                    if cells is not None:
                        cpu.setdefault((shape, naming), {})[size] = seconds
                        print(f"| {shape} | {naming} | {size:,} | {cells} | "
                              f"{' '.join(f'{k}:{v}' for k, v in sorted(planted.items()))} |", flush=True)
                    else:
                        print(f"| {shape} | {naming} | {size:,} | - | failed after {seconds:.1f} s cpu "
                              f"(limit {opts.limit_mb} MB) | | | | | | |", flush=True)
    for (shape, naming), series in cpu.items():
        sizes = sorted(series)
        for first, last in sorted({(sizes[0], 10000), (sizes[0], sizes[-1])}):
            if first < last and last in series:
                exponent = math.log(series[last] / series[first]) / math.log(last / first)
                print(f"growth exponent ({shape}, {naming}, cpu, {first:,} -> {last:,}): {exponent:.2f}")


def run(root: Path, shape: str, opts: argparse.Namespace) -> tuple[float, str | None]:
    """The median cpu seconds of `archlog check` on one workspace, and its table cells up to the
    findings (None when the check failed, e.g. past the memory limit: then the first run's seconds)."""
    runs = [measure(root, shape, opts.limit_mb) for _ in range(opts.repeat)]
    if runs[0][2] is None:
        return runs[0][0], None
    seconds = statistics.median(r[0] for r in runs)
    peak = statistics.median(r[1] for r in runs)
    rules = Counter(f["rule"] for f in runs[0][2]["findings"])
    split, near = phases_apart(root, shape, opts.profile)
    total = sum(split.values())
    largest = ", ".join(f"{k} {v / total:.0%}" for k, v in sorted(split.items(), key=lambda kv: -kv[1])[:3])
    return seconds, (f"{near:,} | {seconds:.1f} | {peak:,.0f} | {split['near-miss'] / total:.1%} | "
                     f"{split['to-clingo'] / total:.1%} | {largest} | "
                     f"{' '.join(f'{r}:{c}' for r, c in sorted(rules.items()))}")


if __name__ == "__main__":
    main()
