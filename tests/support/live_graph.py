"""Run ROS 1 launch files against a private master and read back the live graph.

Debian's ROS 1 packages only import under /usr/bin/python3, so everything ROS
is run as a subprocess; the master is read over XML-RPC with the stdlib.
"""

from __future__ import annotations

import contextlib
import re
import shutil
import subprocess
import tempfile
import threading
import time
import xmlrpc.client
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from archlog import observe
from archlog.testgen import processes

ROSCORE = Path("/usr/bin/roscore")
ROSLAUNCH = Path("/usr/bin/roslaunch")
ROSTOPIC = Path("/usr/bin/rostopic")
SYSTEM_PYTHON = processes.SYSTEM_PYTHON
MONITOR = Path(__file__).resolve().parent / "topic_monitor.py"

_POLL = 0.2  # seconds between master polls
_LAUNCH_GRACE = 3.0  # SIGINT -> SIGKILL grace for roslaunch (and its nodes)
_CORE_GRACE = 2.0  # same for roscore
_ANSI = re.compile(r"\x1b(\[[0-9;]*[A-Za-z]|\][^\x07]*\x07)")  # colours, terminal titles


LiveGraph = observe.Architecture  # the live graph, as archlog's observer reads it


def ros_available() -> bool:
    """True if Debian's roslaunch and roscore are installed."""
    return ROSLAUNCH.is_file() and ROSCORE.is_file()


def launch_graph(
    workspace_src: Path,
    launch_files: list[Path],
    args: dict[str, str] | None = None,
    expect_nodes: int | None = None,
    settle: float = 3.0,
    timeout: float = 30.0,
) -> LiveGraph:
    """Start a private master on 127.0.0.1, roslaunch the files, read the graph, stop everything."""
    with running_system(workspace_src, launch_files, args, expect_nodes, settle, timeout) as (_uri, graph):
        return graph


@contextmanager
def running_system(
    workspace_src: Path,
    launch_files: list[Path],
    args: dict[str, str] | None = None,
    expect_nodes: int | None = None,
    settle: float = 3.0,
    timeout: float = 30.0,
) -> Iterator[tuple[str, LiveGraph]]:
    """Start a private master on 127.0.0.1, roslaunch the files, read the graph, stop everything.

    Returns once the graph has been unchanged for ``settle`` seconds (counted
    from when roslaunch registered with the master) and holds at least
    ``expect_nodes`` non-infrastructure nodes. Raises RuntimeError if roscore or
    roslaunch fails, or if ``timeout`` expires first.
    """
    with live_system(workspace_src, launch_files, args, expect_nodes, settle, timeout) as system:
        yield system.uri, system.graph


@dataclass
class LiveSystem:
    """A launched system on its private master: more ROS processes can be started in it (they
    are stopped with it), topics watched and fed."""

    uri: str
    graph: LiveGraph
    env: dict[str, str]
    logs: Path
    processes: list[subprocess.Popen] = field(default_factory=list)

    def spawn(self, cmd: list[str], name: str) -> subprocess.Popen:
        """Start a process in the system's environment (its output goes to `name`.log)."""
        proc = _spawn(cmd, self.env, self.logs / f"{name}.log")
        self.processes.append(proc)
        return proc

    def log(self, name: str) -> str:
        return _tail(self.logs / f"{name}.log")

    def publish(self, topic: str, type_: str, message: str, rate: float = 5.0) -> subprocess.Popen:
        """Publish `message` (YAML, as rostopic takes it) on `topic` at `rate` Hz until the system stops."""
        return self.spawn([str(ROSTOPIC), "pub", "-r", str(rate), topic, type_, message],
                          f"pub{len(self.processes)}")

    def monitor(self, topics: list[str], connect_timeout: float = 10.0) -> TopicMonitor:
        """Count the messages on `topics` from now on (a rospy subscriber in a subprocess)."""
        env = dict(self.env, ARCHLOG_MONITOR_CONNECT=str(connect_timeout))
        with open(self.logs / "monitor.log", "wb") as log:
            proc = subprocess.Popen([str(SYSTEM_PYTHON), str(MONITOR), *topics], env=env, stdin=subprocess.PIPE,
                                    stdout=subprocess.PIPE, stderr=log, start_new_session=True)
        self.processes.append(proc)
        return TopicMonitor(proc, topics, self.logs / "monitor.log")


class TopicMonitor:
    """Message counts per topic, as the monitor subprocess reports them (timed on arrival here)."""

    def __init__(self, proc: subprocess.Popen, topics: list[str], log: Path) -> None:
        self.proc, self.topics, self.log = proc, list(topics), log
        self._lock = threading.Lock()
        self._counts: dict[str, int] = dict.fromkeys(topics, 0)
        self._ready = threading.Event()
        self.unconnected: list[str] = []
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for raw in self.proc.stdout:
            words = raw.decode(errors="replace").split()
            if words[:1] == ["msg"] and len(words) == 2:
                with self._lock:
                    self._counts[words[1]] = self._counts.get(words[1], 0) + 1
            elif words[:1] == ["ready"]:
                self.unconnected = words[1:]
                self._ready.set()

    def wait_ready(self, timeout: float) -> None:
        """Block until every subscription has connected (or the monitor gave up on some: see
        `unconnected`); RuntimeError if the monitor dies or does not answer in time."""
        end = time.monotonic() + timeout
        while not self._ready.wait(_POLL):
            if self.proc.poll() is not None:
                raise RuntimeError(f"topic monitor exited with code {self.proc.returncode}:\n{_tail(self.log)}")
            if time.monotonic() > end:
                raise RuntimeError(f"topic monitor not ready after {timeout} s:\n{_tail(self.log)}")

    def counts(self) -> dict[str, int]:
        with self._lock:
            return dict(self._counts)

    def wait_until(self, done: Callable[[dict[str, int]], bool], timeout: float) -> dict[str, int]:
        """Poll the counts until `done(counts)` or `timeout` seconds; returns the last counts."""
        end = time.monotonic() + timeout
        while True:
            counts = self.counts()
            if done(counts) or time.monotonic() > end:
                return counts
            time.sleep(_POLL / 2)


@contextmanager
def live_system(
    workspace_src: Path,
    launch_files: list[Path],
    args: dict[str, str] | None = None,
    expect_nodes: int | None = None,
    settle: float = 3.0,
    timeout: float = 30.0,
) -> Iterator[LiveSystem]:
    """`running_system`, yielding the live system itself; every process started through it is
    stopped (and anything left with its ROS_HOME killed) on exit."""
    deadline = time.monotonic() + timeout
    tmp = Path(tempfile.mkdtemp(prefix="archlog-rosgraph-"))
    port = _free_port()
    uri = f"http://127.0.0.1:{port}"
    env = _ros_env(tmp, uri, Path(workspace_src))
    core_log, launch_log = tmp / "roscore.log", tmp / "roslaunch.log"
    core = launch = None
    system: LiveSystem | None = None
    try:
        core = _spawn([str(ROSCORE), "-p", str(port)], env, core_log)
        master = _wait_for_master(uri, core, core_log, deadline)
        known_launchers = _roslaunch_uris(master)

        cmd = [str(ROSLAUNCH), "--screen", "--sigint-timeout", "2", "--sigterm-timeout", "1"]
        cmd += [str(f) for f in launch_files]
        cmd += [f"{k}:={v}" for k, v in (args or {}).items()]
        launch = _spawn(cmd, env, launch_log)
        graph = _wait_for_graph(master, launch, launch_log, known_launchers, expect_nodes, settle, deadline)
        system = LiveSystem(uri, graph, env, tmp)
        yield system
    finally:
        _stop_together([*(system.processes if system else []), launch], _LAUNCH_GRACE)
        _stop(core, _CORE_GRACE)
        _kill_leftovers(tmp)
        shutil.rmtree(tmp, ignore_errors=True)  # errors already carry the log tail


# -- processes (archlog.testgen.processes) ----------------------------------


def _ros_env(tmp: Path, master_uri: str, workspace_src: Path) -> dict[str, str]:
    return processes.ros_env(tmp, master_uri, str(workspace_src))


def _kill_leftovers(tmp: Path) -> None:
    processes.kill_leftovers(f"ROS_HOME={tmp}".encode())


_free_port, _stop, _stop_together, _tail = processes.free_port, processes.stop, processes.stop_together, processes.tail
_pids_with_env, _alive = processes.pids_with_env, processes.alive


def _spawn(cmd: list[str], env: dict[str, str], log: Path) -> subprocess.Popen:
    log.unlink(missing_ok=True)
    return processes.spawn(cmd, env, log)


# -- master ------------------------------------------------------------------


def _master(uri: str):
    return observe.master(uri)


def _call(method, *args):
    return observe.call(method, *args)


def _wait_for_master(uri: str, core: subprocess.Popen, log: Path,
                     deadline: float) -> xmlrpc.client.ServerProxy:
    master = _master(uri)
    while True:
        with contextlib.suppress(OSError, xmlrpc.client.Error):
            _call(master.getSystemState)
            return master
        if core.poll() is not None:
            raise RuntimeError(f"roscore exited with code {core.returncode}:\n{_tail(log)}")
        if time.monotonic() > deadline:
            raise RuntimeError(f"master at {uri} did not come up in time:\n{_tail(log)}")
        time.sleep(_POLL)


def _roslaunch_uris(master: xmlrpc.client.ServerProxy) -> set[str]:
    """Names of /roslaunch/uris/* params: each roslaunch (roscore too) adds one."""
    return {p for p in _call(master.getParamNames) if p.startswith("/roslaunch/uris/")}


def _read_graph(master) -> LiveGraph:
    return observe.read_master(master)


def _wait_for_graph(master: xmlrpc.client.ServerProxy, launch: subprocess.Popen, log: Path,
                    known_launchers: set[str], expect_nodes: int | None, settle: float,
                    deadline: float) -> LiveGraph:
    graph: LiveGraph | None = None
    changed_at: float | None = None  # None until our roslaunch shows up on the master
    while True:
        if launch.poll() is not None:
            raise RuntimeError(
                f"roslaunch exited early with code {launch.returncode}:\n{_tail(log)}")
        now = time.monotonic()
        if changed_at is None and _roslaunch_uris(master) - known_launchers:
            changed_at = now
        current = _read_graph(master)
        if current != graph:
            graph = current
            if changed_at is not None:
                changed_at = now
        enough = expect_nodes is None or len(graph.nodes) >= expect_nodes
        if changed_at is not None and enough and now - changed_at >= settle:
            return graph
        if now > deadline:
            want = f"{expect_nodes} nodes" if expect_nodes is not None else "a stable graph"
            raise RuntimeError(
                f"timed out waiting for {want}; last graph has nodes "
                f"{sorted(graph.nodes)}\nroslaunch log tail:\n{_tail(log)}")
        time.sleep(_POLL)
