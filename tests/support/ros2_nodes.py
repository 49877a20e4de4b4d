"""rclpy nodes started for real, as plain processes on a private DDS domain, with the name,
namespace, remaps and parameters archlog recovered for each instance (the `--ros-args` launch_ros
would pass), and the live graph read by archlog's own rclpy observer (archlog.observe_ros2) in a
separate process: the test process never imports rclpy (test_testgen puts a stand-in rclpy on
sys.path).

Domains: every test takes its own ROS_DOMAIN_ID from ARCHLOG_TEST_ROS_DOMAINS (default 100-199),
split between pytest-xdist workers, so parallel tests never see each other's nodes. Discovery
stays on this machine (ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST).
"""

from __future__ import annotations

import functools
import importlib.util
import itertools
import json
import os
import shlex
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from archlog.analysis import Analysis
from archlog.observe_ros2 import Port, Ros2Graph
from archlog.testgen import processes

_counter = itertools.count()


@functools.cache
def rclpy_available() -> bool:
    """rclpy and its native libraries load in a fresh interpreter (not only that the module exists)."""
    if importlib.util.find_spec("rclpy") is None:
        return False
    done = subprocess.run([sys.executable, "-c", "import rclpy, rclpy.action"], capture_output=True, timeout=60)
    return done.returncode == 0


def private_domain() -> int:
    """A ROS_DOMAIN_ID no other test of this run uses (while fewer tests than the range holds run)."""
    low, high = (int(x) for x in os.environ.get("ARCHLOG_TEST_ROS_DOMAINS", "100-199").split("-"))
    worker = int(os.environ.get("PYTEST_XDIST_WORKER", "gw0")[2:] or 0)
    workers = int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1"))
    span = max((high - low + 1) // workers, 1)
    return low + worker * span + next(_counter) % span


def ros2_env(domain: int, home: Path, pythonpath: tuple[Path, ...] = ()) -> dict[str, str]:
    env = dict(os.environ, ROS_DOMAIN_ID=str(domain), ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST",
               ROS_HOME=str(home), ROS_LOG_DIR=str(home / "log"), PYTHONUNBUFFERED="1")
    env.pop("ROS_LOCALHOST_ONLY", None)  # deprecated; it would override the discovery range
    if pythonpath:
        env["PYTHONPATH"] = os.pathsep.join([str(p) for p in pythonpath] + [env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    return env


@dataclass(frozen=True)
class NodeRun:
    """How to start one node instance: a script (`entry` empty) or a console_scripts entry point
    `module:function` importable from `root`."""

    name: str  # full node name, /ns/base
    source: Path
    root: Path
    entry: str = ""
    remaps: tuple[tuple[str, str], ...] = ()
    params: tuple[tuple[str, object], ...] = ()
    words: tuple[str, ...] = ()  # the instance's own command-line arguments (launch args=/arguments=)

    def argv(self) -> list[str]:
        namespace, _, base = self.name.rpartition("/")
        if self.entry:
            module, _, function = self.entry.partition(":")
            start = ["-c", f"import sys; from {module} import {function} as main; sys.exit(main())"]
        else:
            start = [str(self.source)]
        ros_args = ["-r", f"__node:={base}", "-r", f"__ns:={namespace or '/'}"]
        for source, target in self.remaps:
            ros_args += ["-r", f"{source}:={target}"]
        for name, value in self.params:
            ros_args += ["-p", f"{name}:={json.dumps(value)}"]
        return [sys.executable, *start, *self.words, "--ros-args", *ros_args]


@contextmanager
def running_nodes(runs: list[NodeRun], domain: int) -> Iterator[list[subprocess.Popen]]:
    """The nodes running on `domain`; each is stopped (SIGINT, then SIGKILL to its process group) on exit."""
    procs: list[subprocess.Popen] = []
    with tempfile.TemporaryDirectory(prefix="archlog-ros2-") as tmp:
        try:
            for run in runs:
                env = ros2_env(domain, Path(tmp), (run.root,))
                procs.append(subprocess.Popen(run.argv(), env=env, cwd=tmp, stdout=subprocess.DEVNULL,
                                              stderr=subprocess.PIPE, start_new_session=True))
            yield procs
        finally:
            for proc in procs:
                stop(proc)


def stop(proc: subprocess.Popen) -> None:
    """Stop a process started in a session of its own (SIGINT, then SIGKILL to its group) and close its pipe."""
    processes.stop(proc, 5.0)
    if proc.stderr is not None:
        proc.stderr.close()


def rclpy_nodes(analysis: Analysis) -> set[str]:
    return {str(n) for n, origin in analysis.store.rows("node_source") if origin == "python"}


def rclpy_runs(analysis: Analysis) -> list[NodeRun]:
    """How to start every rclpy instance as launch_ros would, with what archlog recovered for it."""
    runs = []
    for node in analysis.config.nodes:
        if node.name not in rclpy_nodes(analysis):
            continue
        executable = analysis.workspace.packages[node.pkg].executables[node.type]
        source = executable.sources[0]
        depth = len(executable.entry.partition(":")[0].split(".")) + (source.name == "__init__.py")
        root = source.parents[depth - 1] if executable.entry else source.parent
        prefix = node.name + "/"
        params = tuple((key[len(prefix):], value) for key, (value, _elem) in analysis.config.params.items()
                       if key.startswith(prefix) and "/" not in key[len(prefix):])
        runs.append(NodeRun(node.name, source, root, executable.entry, tuple((a, b) for a, b, _e in node.remaps), params,
                            tuple(shlex.split(node.args))))
    return runs


OBSERVE = """
import json, sys
from archlog.observe_ros2 import read_graph
graph = read_graph(int(sys.argv[1]), settle=float(sys.argv[2]), expect=frozenset(sys.argv[4:]), timeout=float(sys.argv[3]))
print(json.dumps({"nodes": sorted(graph.nodes), "ports": sorted(graph.ports),
                  "infrastructure": sorted(graph.infrastructure), "qos": sorted(graph.qos)}))
"""


def observe(domain: int, expect: set[str], settle: float = 1.5, timeout: float = 30.0) -> Ros2Graph:
    """The live graph of `domain` as archlog.observe_ros2 reads it, once the `expect`ed nodes are
    there and discovery has settled (bounded by `timeout`)."""
    with tempfile.TemporaryDirectory(prefix="archlog-observer-") as tmp:
        done = subprocess.run([sys.executable, "-c", OBSERVE, str(domain), str(settle), str(timeout), *sorted(expect)],
                              env=ros2_env(domain, Path(tmp)), capture_output=True, text=True, timeout=timeout + 30)
    if done.returncode != 0:
        raise RuntimeError(f"the observer failed: {done.stderr[-2000:]}")
    data = json.loads(done.stdout)

    def ports(key: str) -> frozenset[Port]:
        return frozenset((k, n, name, t) for k, n, name, t in data[key])

    return Ros2Graph(frozenset(data["nodes"]), ports("ports"), ports("infrastructure"),
                     frozenset((n, t, d, p, v) for n, t, d, p, v in data["qos"]))

