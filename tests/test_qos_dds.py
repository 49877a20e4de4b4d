"""QoS rules agree with DDS: publisher/subscriber pairs over every policy AL501-AL505 read
(reliability, durability, deadline, liveliness, lease duration; unset and system-default values
too) are written as rclpy code, read by archlog, and run on a private DDS domain; for every pair,
archlog reports a QoS finding exactly when DDS raises the incompatible-QoS event instead of
matching. bench/qos_dds.py writes the same matrix to bench/results/qos_dds.md."""

from __future__ import annotations

from pathlib import Path

from conftest import requires_rclpy
from support.qos_dds import PAIRS, QOS_RULES, archlog_verdicts, dds_verdicts, matrix, write_workspace
from support.ros2_nodes import private_domain

pytestmark = requires_rclpy()


def test_archlog_qos_verdicts_equal_dds_verdicts(tmp_path: Path) -> None:
    workspace = write_workspace(tmp_path)
    said, problems = archlog_verdicts(workspace)
    assert problems == []  # archlog read every profile: its silence on a pair is a verdict
    dds = dds_verdicts(workspace, private_domain())
    assert set(dds.values()) == {"matched", "incompatible"} and len(dds) == len(PAIRS)  # DDS decided every pair
    rows = matrix(said, dds)
    assert [r for r in rows if not r["agree"]] == []
    # every rule is exercised by at least one incompatible pair
    assert {rule for r in rows for rule in r["archlog"]} == set(QOS_RULES)  # type: ignore[attr-defined]
