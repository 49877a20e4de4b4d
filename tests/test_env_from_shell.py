"""--env-from-shell (issue 30): a local user's shell variables that launch files ask for are read
with the switch, named in an env-from-shell note; without it (CI) they stay unknown; a name that
looks like a secret's is never read; a configuration file cannot turn the switch on."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from archlog.cli import main
from archlog.errors import ConfigError

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2"><name>rig</name><version>0.0.1</version><description>rig</description>
<maintainer email="rig@example.com">rig</maintainer><license>MIT</license></package>
"""
LAUNCH = """<launch>
  <node pkg="rig_$(env RIG_SENSOR)" type="driver" name="driver"/>
  <node pkg="rig_$(optenv RIG_API_TOKEN none)" type="uploader" name="uploader"/>
</launch>
"""


@pytest.fixture()
def workspace(tmp_path: Path) -> Path:
    (tmp_path / "rig" / "launch").mkdir(parents=True)
    (tmp_path / "rig" / "package.xml").write_text(PACKAGE_XML)
    (tmp_path / "rig" / "launch" / "rig.launch").write_text(LAUNCH)
    return tmp_path


def _diagnostics(workspace: Path, *options: str) -> list[dict]:
    shell = {"RIG_SENSOR": "kinect", "RIG_API_TOKEN": "hunter2"}
    result = CliRunner().invoke(main, ["check", str(workspace), "--launch", "rig/launch/rig.launch", "--format",
                                       "json", "--quiet", *options], env=shell)
    assert result.exit_code in (0, 1), result.output
    assert "hunter2" not in result.output
    return json.loads(result.output)["diagnostics"]


def test_shell_variables_are_read_only_with_the_switch(workspace: Path) -> None:
    without = {(d["code"], d["message"].split(" ")[2]) for d in _diagnostics(workspace)
               if d["code"] in ("env-not-given", "env-from-shell")}
    assert ("env-not-given", "RIG_SENSOR") in without
    assert not any(code == "env-from-shell" for code, _ in without)
    shell = _diagnostics(workspace, "--env-from-shell")
    notes = [d for d in shell if d["code"] == "env-from-shell"]
    assert [(n["file"], n["line"], n["message"]) for n in notes] == \
        [("rig/launch/rig.launch", 1, "read from this shell (--env-from-shell): RIG_SENSOR")]
    packages = {d["message"] for d in shell if d["code"] == "no-model"}
    assert any("rig_kinect" in m for m in packages) and any("rig_none" in m for m in packages)
    assert not any(d["code"] == "env-not-given" and "RIG_SENSOR" in d["message"] for d in shell)


def test_a_given_value_wins_over_the_shell(workspace: Path) -> None:
    given = _diagnostics(workspace, "--env-from-shell", "--env", "RIG_SENSOR=lidar")
    assert any("rig_lidar" in d["message"] for d in given if d["code"] == "no-model")
    assert not any(d["code"] == "env-from-shell" for d in given)


def test_a_configuration_file_cannot_turn_it_on(workspace: Path) -> None:
    (workspace / "archlog.toml").write_text("env-from-shell = true\n")
    result = CliRunner().invoke(main, ["check", str(workspace), "--launch", "rig/launch/rig.launch", "--quiet"],
                                env={"RIG_SENSOR": "kinect"})
    assert isinstance(result.exception, ConfigError) and "unknown key(s) env-from-shell" in str(result.exception)
    assert "kinect" not in result.output
