"""C++ recovery does not depend on whether Debian's ROS 1 headers are installed (issue 28): the
corpus systems with ROS 1 C++ nodes give the same facts and findings with the ROS folders of
/usr/include hidden (bind mounts in a private mount namespace, as on a machine without ROS) as
with them; their files are then read with archlog's stand-in headers, which a note says, and
none falls back to the tokens."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SYSTEMS = [f"corpus/{case}/buggy" for case in (
    "ros1/action_type_mismatch", "ros1/camera_info_remap", "ros1/handle_namespace_remap", "ros1/inprocess_nodelet",
    "ros1/linked_library_typo", "ros1/misplaced_remap", "ros1/namespace_prefix", "ros1/nodelet_manager_name",
    "ros1/planner_service_typo", "ros1/sync_topic_typo", "ros1/topic_typo", "ros1/type_mismatch",
    "ros1/unused_remap_duplicate", "behavior/empty_checks", "behavior/mode_switch", "behavior/reactive_pipeline",
    "behavior/state_flag", "behavior/timer_output", "behavior/virtual_methods", "behavior/wait_first_pose")]


def _ros_include_folders() -> list[Path]:
    """Debian's ROS 1 header folders: those of packages with a manifest in /usr/share, and roscpp's ros/."""
    return [d for d in sorted(Path("/usr/include").iterdir())
            if d.is_dir() and (d.name == "ros" or (Path("/usr/share") / d.name / "package.xml").is_file())]


def _can_unshare() -> bool:
    if os.geteuid() != 0 or shutil.which("unshare") is None or not Path("/usr/include/ros/ros.h").is_file():
        return False
    return subprocess.run(["unshare", "-m", "true"], capture_output=True).returncode == 0


CHUNKS = [SYSTEMS[k::4] for k in range(4)]  # four tests, so that the suite's workers share them


def _fingerprint(tmp_path: Path, systems: list[str], hide: bool) -> dict:
    name = "hidden" if hide else "installed"
    out = tmp_path / f"{name}.json"
    command = [sys.executable, "bench/fingerprint.py", str(out), "--systems", *systems]
    if hide:
        empty = tmp_path / "empty"
        empty.mkdir()
        mounts = " && ".join(f"mount --bind {empty} {folder}" for folder in _ros_include_folders())
        command = ["unshare", "-m", "--propagation", "private", "sh", "-c", f"{mounts} && exec \"$@\"", "sh", *command]
    env = {**os.environ, "ARCHLOG_CACHE_DIR": str(tmp_path / f"cache-{name}")}
    done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True, timeout=1200)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(out.read_text())


@pytest.mark.skipif(not _can_unshare(), reason="needs root, unshare and Debian's ROS 1 headers to hide")
@pytest.mark.parametrize("systems", CHUNKS, ids=lambda chunk: chunk[0].split("/")[2])
def test_cpp_corpus_same_without_ros_headers(tmp_path: Path, systems: list[str]) -> None:
    installed, hidden = _fingerprint(tmp_path, systems, hide=False), _fingerprint(tmp_path, systems, hide=True)
    for system in systems:
        notes = [d for d in hidden[system]["diagnostics"] if d.endswith("[cpp-ros1-stand-in]")]
        assert notes, f"{system}: no file was read with the stand-in headers"
        hidden[system]["diagnostics"] = [d for d in hidden[system]["diagnostics"] if d not in notes]
        assert hidden[system] == installed[system], system  # every fact, finding and other diagnostic
