"""A near-miss finding on a port named by a parameter the launch file sets (issue 30): the report
names the value the node uses and places the finding at the <param> line, the code that reads the
parameter being the first related location (corpus ros1/param_topic_value)."""

from __future__ import annotations

import json

from click.testing import CliRunner
from conftest import CORPUS

from archlog.cli import main


def _findings(variant: str) -> list[dict]:
    result = CliRunner().invoke(main, ["check", str(CORPUS / "param_topic_value" / variant), "--launch",
                                       "gripper_panel/launch/gripper.launch", "--format", "json", "--quiet",
                                       "--fail-on", "never"])
    assert result.exit_code == 0, result.output
    return json.loads(result.output)["findings"]


def test_the_finding_is_at_the_parameter_the_value_is_written_in() -> None:
    (finding,) = _findings("buggy")
    assert finding["rule"] == "AL102"
    assert finding["subjects"]["topics"][0] == "/gripper/joint_stat"
    where = [(loc["file"].split("buggy/", 1)[-1], loc["line"], loc["role"]) for loc in finding["locations"]]
    assert where[:2] == [("src/gripper_panel/launch/gripper.launch", 4, "primary"),
                         ("src/gripper_panel/scripts/gripper_panel.py", 11, "related")]


def test_the_clean_twin_is_silent() -> None:
    assert _findings("clean") == []
