"""`archlog observe --ros2` and `archlog diff` end to end on a live ROS 2 graph: the rclpy nodes of a
corpus system run on a private DDS domain, archlog reads the domain with rclpy and compares it with
the recovery of both twins."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from conftest import CORPUS_ROS2, ROOT, load_case, requires_rclpy, run_case
from support.ros2_nodes import observe, private_domain, rclpy_runs, ros2_env, running_nodes

pytestmark = requires_rclpy()

SYSTEM = CORPUS_ROS2 / "yaml_remap_near_miss"  # three rclpy nodes, nothing else


def archlog(*args: str | Path, env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *map(str, args)], capture_output=True, text=True,
                          cwd=ROOT, timeout=120, env=env)


def test_observe_ros2_then_diff(tmp_path: Path) -> None:
    clean, buggy = SYSTEM / "clean", SYSTEM / "buggy"
    analysis, _findings = run_case(clean)
    runs = rclpy_runs(analysis)
    domain = private_domain()
    observed = tmp_path / "observed.json"
    with running_nodes(runs, domain):
        assert observe(domain, {r.name for r in runs}).nodes >= {r.name for r in runs}  # all up: observe as a user would
        result = archlog("observe", "--ros2", "--domain", domain, "--settle", "1.5", "--output", observed,
                         env=ros2_env(domain, tmp_path))
    assert result.returncode == 0, result.stderr
    seen = json.loads(observed.read_text())
    assert set(seen) == {"nodes", "publishers", "subscribers", "services", "clients", "action_servers",
                         "action_clients", "qos"}
    assert seen["nodes"] == sorted(r.name for r in runs) == ["/robot1/base", "/robot1/smoother", "/robot1/teleop"]
    assert ["/robot1/smoother", "/robot1/cmd_vel_smoothed", "geometry_msgs/msg/Twist"] in seen["publishers"]
    # infrastructure (/rosout, /parameter_events, parameter services) is left out
    assert all(not t.endswith(("/rosout", "/parameter_events")) for _n, t, _ty in seen["publishers"])
    assert seen["services"] == []
    launches = [w for spec in load_case(clean)["launch"] for w in ("--launch", spec)]
    same = archlog("diff", clean, *launches, "--observed", observed, "--format", "json")
    assert same.returncode == 0, same.stdout
    table = json.loads(same.stdout)
    assert set(table) == set(seen)
    assert table["publishers"]["recovered"] == table["publishers"]["observed"] == 2
    assert table["subscribers"]["recovered"] == table["subscribers"]["observed"] == 2
    # the buggy twin remaps the base's input elsewhere: the diff says where
    changed = archlog("diff", buggy, *launches, "--observed", observed)
    assert changed.returncode == 1
    assert "only recovered subscribers: ['/robot1/base', '/robot1/cmd_vel_smooth']" in changed.stdout
    assert "only observed subscribers: ['/robot1/base', '/robot1/cmd_vel_smoothed']" in changed.stdout


def test_observe_ros2_without_rclpy_is_a_clear_error(tmp_path: Path) -> None:
    """Where rclpy does not import (a broken or absent install), exit 2 with a message, no traceback."""
    broken = tmp_path / "rclpy"
    broken.mkdir()
    (broken / "__init__.py").write_text("raise ImportError('librcl.so: cannot open shared object file')\n")
    env = ros2_env(private_domain(), tmp_path, (tmp_path,))
    result = archlog("observe", "--ros2", env=env)
    assert result.returncode == 2
    assert "rclpy is not importable" in result.stderr and "archlog[ros2]" in result.stderr
    assert "Traceback" not in result.stderr
