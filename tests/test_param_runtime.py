"""Runtime proof of AL403 (issue 29) with PyPI rclpy: the corpus follower is started with the parameters
archlog recovers from its launch and parameter files; in the buggy case (a misspelled parameter) its live
subscription follows the declared default, /scan, exactly as the finding says; in the clean twin it follows
the value set, /scan_filtered. Processes run on a private ROS domain over loopback, bounded in time."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest
from conftest import CORPUS_ROS2, run_case

from archlog.values import Unknown

rclpy = pytest.importorskip("rclpy")

CASE = CORPUS_ROS2 / "param_name_typo_py"
NODE = "/follower"
DOMAIN = "77"


def _parameters(variant: Path) -> list[str]:
    """`-p name:=value` for every parameter archlog says the configuration gives the follower."""
    analysis, _findings = run_case(variant)
    args: list[str] = []
    for param, node, local in analysis.store.rows("param_of"):
        value = next(v for p, v, _e in analysis.store.rows("param") if p == param)
        if node == NODE and not isinstance(value, Unknown):
            args += ["-p", f"{local}:={value}"]
    return args


def _live_subscriptions(variant: Path) -> set[str]:
    """The topics the running follower subscribes, read from the live graph."""
    env = {**os.environ, "ROS_DOMAIN_ID": DOMAIN, "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}
    script = variant / "src" / "follow_me" / "follow_me" / "follower.py"
    proc = subprocess.Popen([sys.executable, str(script), "--ros-args", "-r", "__node:=follower",
                             *_parameters(variant)], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    os.environ["ROS_DOMAIN_ID"], os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = DOMAIN, "LOCALHOST"
    context = rclpy.context.Context()
    rclpy.init(context=context)
    observer = rclpy.create_node("param_observer", context=context)
    try:
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            if proc.poll() is not None:
                raise AssertionError(f"the follower exited: {proc.stderr.read().decode() if proc.stderr else ''}")
            if ("follower", "/") in observer.get_node_names_and_namespaces():
                topics = {t for t, _types in observer.get_subscriber_names_and_types_by_node("follower", "/")}
                if topics:
                    return topics
            time.sleep(0.2)
        raise AssertionError("the follower did not appear in the graph within 30 s")
    finally:
        observer.destroy_node()
        rclpy.shutdown(context=context)
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def test_misspelled_parameter_keeps_the_default_topic() -> None:
    _analysis, findings = run_case(CASE / "buggy")
    [finding] = [f for f in findings if f.rule.id == "AL403"]
    assert "scan_topc" in finding.message and "candidate: scan_topic" in finding.message
    assert "subscribes /scan" in finding.message
    assert not [f for f in findings if f.rule.id in ("AL102", "AL103", "AL104", "AL601")]
    assert _live_subscriptions(CASE / "buggy") == {"/scan"}


def test_clean_twin_follows_the_value_set() -> None:
    _analysis, findings = run_case(CASE / "clean")
    assert findings == []
    assert _live_subscriptions(CASE / "clean") == {"/scan_filtered"}
