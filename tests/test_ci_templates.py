"""The shipped pre-commit hook and CI templates work as shipped: the hook's `files` pattern covers
every input archlog reads, and its command without args checks the repository's one named system;
each CI template installs archlog from a source it names (not an unpublished package name) and
runs the analysis once, writing its report and failing on errors."""

from __future__ import annotations

import json
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from conftest import CORPUS, ROOT

LAUNCH = "waypoint_nav/launch/follow_waypoints.launch"


def repository(tmp: Path) -> Path:
    repo = tmp / "repo"
    shutil.copytree(CORPUS / "topic_typo" / "buggy" / "src", repo / "src")
    subprocess.run(["git", "init", "-q", str(repo)], check=True, timeout=60)
    return repo


def run(command: list[str], cwd: Path) -> subprocess.CompletedProcess:
    assert command[0] == "archlog"
    return subprocess.run([sys.executable, "-m", "archlog", *command[1:]], capture_output=True, text=True, cwd=cwd,
                          timeout=300)


def test_pre_commit_hook_runs_without_args_and_watches_every_input(tmp_path: Path) -> None:
    (hook,) = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
    assert hook["language"] == "python" and (ROOT / "pyproject.toml").is_file()  # pre-commit pip-installs this repo
    files = re.compile(hook["files"])
    for name in ("archlog.toml", "team_rules/EX001.lp", "pkg/urdf/robot.urdf.xacro", "pkg/launch/a.launch",
                 "pkg/launch/a.launch.py", "pkg/package.xml", "pkg/CMakeLists.txt", "pkg/src/node.cpp"):
        assert files.search(name), name
    repo = repository(tmp_path)
    (repo / "archlog.toml").write_text(f'[systems.robot]\npaths = ["src"]\nlaunch = ["{LAUNCH}"]\n')
    result = run([*shlex.split(hook["entry"]), *hook["args"]], repo)
    assert result.returncode == 1, result.stderr  # the near miss, not a usage error
    assert "AL102" in result.stdout and "1 finding (1 error" in result.stdout


@pytest.mark.parametrize(("template", "report"), [("github-actions.yml", "archlog.sarif"),
                                                  ("gitlab-ci.yml", "gl-code-quality-report.json")])
def test_ci_template_installs_from_a_source_and_analyses_once(template: str, report: str, tmp_path: Path) -> None:
    text = (ROOT / "docs" / "ci" / template).read_text()
    assert not re.search(r"pip install archlog\b", text) and 'pip install "$ARCHLOG_SOURCE"' in text
    commands = re.findall(r"(?:run: |- )(archlog check[^\n]*)", text)
    assert len(commands) == 1, commands  # one analysis: the report and the exit status
    repo = repository(tmp_path)
    command = shlex.split(commands[0].replace("my_robot_bringup/launch/robot.launch", LAUNCH))
    result = run(command, repo)
    assert result.returncode == 1, result.stderr  # fails on the error
    written = json.loads((repo / report).read_text())
    assert written  # and the report was written for the upload
    assert "if: always()" in text or "when: always" in text
