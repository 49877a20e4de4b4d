"""ROS 1 processes on a private loopback master: the environment, starting a process in a
session of its own, stopping process groups, and killing what a run left behind (roslaunch starts
each node in a session of its own, so a process is found by its private ROS_HOME instead)."""

from __future__ import annotations

import contextlib
import os
import random
import re
import signal
import socket
import subprocess
import time
from collections.abc import Sequence
from pathlib import Path

SYSTEM_PYTHON = Path("/usr/bin/python3")  # the one Debian's rospy imports under
ROSCORE = Path("/usr/bin/roscore")
_ANSI = re.compile(r"\x1b(\[[0-9;]*[A-Za-z]|\][^\x07]*\x07)")  # colours, terminal titles


def free_port() -> int:
    """A port on 127.0.0.1 that binds now, below Linux's ephemeral range (32768-60999): a port the
    kernel picked would be handed out again to any outgoing connection before the master binds it."""
    for port in random.SystemRandom().sample(range(20000, 32768), 200):  # not the seeded `random` of a test
        with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
            try:
                s.bind(("127.0.0.1", port))
            except OSError:
                continue
            return port
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def ros_env(tmp: Path, master_uri: str, package_path: str) -> dict[str, str]:
    """This environment for a private master on 127.0.0.1, ROS_HOME in `tmp`, Debian's python first."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("ROS_IP", "ROS_NAMESPACE", "PYTHONPATH", "PYTHONHOME")}
    env.update(
        ROS_MASTER_URI=master_uri,
        ROS_HOSTNAME="127.0.0.1",
        ROS_HOME=str(tmp),  # also the marker kill_leftovers looks for
        ROS_LOG_DIR=str(tmp / "log"),
        ROS_PACKAGE_PATH=package_path,
        PATH="/usr/bin:" + env.get("PATH", ""),  # `#!/usr/bin/env python3` must find Debian's
        PYTHONUNBUFFERED="1",
    )
    return env


def spawn(cmd: list[str], env: dict[str, str], log: Path, **kwargs) -> subprocess.Popen:
    """Start `cmd` in a session of its own, its output appended to `log`."""
    with open(log, "ab") as out:
        return subprocess.Popen(cmd, env=env, stdin=kwargs.pop("stdin", subprocess.DEVNULL), stdout=out,
                                stderr=subprocess.STDOUT, start_new_session=True, **kwargs)


def stop(proc: subprocess.Popen | None, grace: float) -> None:
    """SIGINT the process group, SIGKILL it after ``grace`` seconds, reap."""
    if proc is None:
        return
    for sig, wait in ((signal.SIGINT, grace), (signal.SIGKILL, 1.0)):
        if proc.poll() is not None:
            break
        try:
            os.killpg(proc.pid, sig)
        except ProcessLookupError:
            break
        with contextlib.suppress(subprocess.TimeoutExpired):
            proc.wait(wait)
    with contextlib.suppress(ProcessLookupError):  # the leader may be gone while group members linger
        os.killpg(proc.pid, signal.SIGKILL)


def stop_together(procs: Sequence[subprocess.Popen | None], grace: float) -> None:
    """`stop` for several processes at once: SIGINT every group, one shared grace, SIGKILL the rest."""
    running = [p for p in procs if p is not None and p.poll() is None]
    for proc in running:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGINT)
    end = time.monotonic() + grace
    while any(p.poll() is None for p in running) and time.monotonic() < end:
        time.sleep(0.05)
    for each in procs:
        stop(each, 0.0)


def kill_leftovers(marker: bytes) -> None:
    """SIGKILL any process whose environment holds `marker` (KEY=value), and wait until they are gone."""
    pids = [pid for pid in pids_with_env(marker) if pid != os.getpid()]
    for pid in pids:
        with contextlib.suppress(ProcessLookupError):
            os.kill(pid, signal.SIGKILL)
    end = time.monotonic() + 2.0
    while pids and time.monotonic() < end:
        pids = [p for p in pids if alive(p)]
        time.sleep(0.05)


def pids_with_env(entry: bytes) -> list[int]:
    """Pids of live processes whose environment contains ``entry`` (KEY=value)."""
    found = []
    for d in Path("/proc").iterdir():
        if not d.name.isdigit():
            continue
        try:
            if entry in (d / "environ").read_bytes().split(b"\0"):
                found.append(int(d.name))
        except OSError:
            continue
    return found


def alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            return f.read().rsplit(b")", 1)[1].split()[0] != b"Z"
    except (OSError, IndexError):
        return False


def tail(log: Path, lines: int = 40) -> str:
    try:
        text = log.read_text(errors="replace")
    except OSError:
        return "(no log)"
    return "\n".join(_ANSI.sub("", text).splitlines()[-lines:])
