"""The README's example on a machine without Debian's ROS or clang packages (the libclang wheel
only): the same findings, and at most a one-line diagnostic naming the header that was missing
(issue 14) besides the note that the stand-in ROS 1 headers were read. Debian's files are hidden
with bind mounts in a private mount namespace."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ["check", "corpus/ros1/topic_typo/buggy", "--launch", "waypoint_nav/launch/follow_waypoints.launch",
           "--format", "json"]
HIDDEN = ["/usr/include", "/usr/share", "/usr/lib/python3", *map(str, Path("/usr/lib").glob("llvm-*"))]


def _can_unshare() -> bool:
    if os.geteuid() != 0 or shutil.which("unshare") is None:
        return False
    return subprocess.run(["unshare", "-m", "true"], capture_output=True).returncode == 0


def _report(tmp_path: Path, hide: bool) -> dict:
    cache = tmp_path / ("cache-bare" if hide else "cache-full")
    env = {**os.environ, "ARCHLOG_CACHE_DIR": str(cache)}
    command = [sys.executable, "-m", "archlog", *EXAMPLE]
    if hide:
        empty = tmp_path / "empty"
        empty.mkdir()
        mounts = " && ".join(f"mount --bind {empty} {path}" for path in HIDDEN)
        script = f"{mounts} && exec \"$@\""
        command = ["unshare", "-m", "--propagation", "private", "sh", "-c", script, "sh", *command]
    done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 1, done.stderr
    assert "Traceback" not in done.stderr
    return json.loads(done.stdout)


@pytest.mark.skipif(not _can_unshare(), reason="needs root and unshare to hide Debian's files")
def test_readme_example_without_ros_or_clang_packages(tmp_path: Path) -> None:
    full, bare = _report(tmp_path, hide=False), _report(tmp_path, hide=True)

    def findings(report: dict) -> list[tuple]:
        return [(f["rule"], f["message"], [(loc["file"], loc["line"]) for loc in f["locations"]])
                for f in report["findings"]]

    assert findings(bare) == findings(full)
    assert [f["rule"] for f in bare["findings"]] == ["AL102"]
    extra = [d for d in bare["diagnostics"] if d not in full["diagnostics"]]
    # ros/ros.h is missing: read with the stand-in ROS 1 headers (a note), but the C++ library they
    # include is hidden too: one line names the header not found
    assert sorted(d["code"] for d in extra) == ["cpp-compile", "cpp-ros1-stand-in"]
    missing = next(d["message"] for d in extra if d["code"] == "cpp-compile")
    assert "file not found" in missing and "\n" not in missing
