"""Rules as a workbench: configuration and profiles, rule tests, queries from the command line."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import CORPUS, ROOT

from archlog.config import Config, load_config
from archlog.errors import ConfigError
from archlog.rules.ruleset import load_rules

BUGGY = CORPUS / "topic_typo" / "buggy"
LAUNCH = ["--launch", "waypoint_nav/launch/follow_waypoints.launch"]


def archlog(*args: str | Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *map(str, args)], capture_output=True, text=True,
                          cwd=ROOT, timeout=300)


@pytest.mark.parametrize("folder", ["archlog/rules/builtin", "docs/examples/rules"])
def test_rule_fixtures_match_their_expected_findings(folder: str, update_goldens: bool) -> None:
    result = archlog("test-rules", folder, *(["--update"] if update_goldens else []))
    assert result.returncode == 0, result.stdout
    assert "all passed" in result.stdout


def test_test_rules_shows_a_diff_on_mismatch(tmp_path: Path) -> None:
    case = tmp_path / "tests" / "one"
    case.mkdir(parents=True)
    (case / "facts.json").write_text(json.dumps({"service_client": [["p1", "/a", "/srv", "t/T"]],
                                                 "location": [["p1", "a.py", 2, 1]]}))
    message = "/a calls service /srv (t/T), which no node provides"
    (case / "findings.expected").write_text(f"AL201 a.py:3 /srv: {message}\n")
    result = archlog("test-rules", tmp_path)
    assert result.returncode == 1
    assert f"-AL201 a.py:3 /srv: {message}" in result.stdout and f"+AL201 a.py:2 /srv: {message}" in result.stdout
    (case / "findings.expected").write_text("AL201 a.py:2 /srv: an older wording\n")
    assert archlog("test-rules", tmp_path).returncode == 1  # the message is pinned too
    updated = archlog("test-rules", tmp_path, "--update")
    assert updated.returncode == 0 and f"wrote {case / 'findings.expected'}" in updated.stdout
    assert (case / "findings.expected").read_text() == f"AL201 a.py:2 /srv: {message}\n"
    again = archlog("test-rules", tmp_path, "--update")
    assert again.returncode == 0 and "wrote" not in again.stdout


def test_profiles_select_ignore_and_severity(tmp_path: Path) -> None:
    rules = {r.id: r for r in load_rules([]).rules}
    assert not load_config(None, "ci").applies(rules["AL104"])  # low precision
    assert load_config(None, "audit").applies(rules["AL104"])
    assert load_config(None, "ci").near_miss_threshold == 0.4
    toml = tmp_path / "archlog.toml"
    toml.write_text('select = ["topics"]\nignore = ["AL103"]\n[severity]\nAL102 = "note"\n'
                    '[profiles.strict]\nnear-miss-threshold = 0.3\n')
    config = load_config(toml, None)
    kept = {r.id: r.severity for r in config.adjust(list(rules.values()))}
    assert set(kept) == {"AL101", "AL102", "AL104", "AL105", "AL106", "AL501", "AL502", "AL503", "AL504", "AL505", "AL601"}
    assert kept["AL102"] == "note"
    assert load_config(toml, "strict").near_miss_threshold == 0.3
    toml.write_text("colour = 1\n")
    with pytest.raises(ConfigError):
        load_config(toml, None)
    assert Config().applies(rules["AL301"])


def test_pyproject_configuration_applies_to_check(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text('[tool.archlog]\n[tool.archlog.severity]\nAL102 = "warning"\n')
    result = archlog("check", BUGGY, *LAUNCH, "--config", tmp_path / "pyproject.toml", "--format", "json")
    assert result.returncode == 0  # the only finding is now a warning
    assert [f["severity"] for f in json.loads(result.stdout)["findings"]] == ["warning"]
    assert archlog("check", BUGGY, *LAUNCH, "--profile", "nope").returncode == 2


def test_query_command_formats_and_errors() -> None:
    goal = "subscriber(_, N, T, _), not published(T)"
    table = archlog("query", BUGGY, *LAUNCH, goal)
    assert table.returncode == 0 and "/rover/base_waypoint" in table.stdout and "1 result" in table.stdout
    as_json = json.loads(archlog("query", BUGGY, *LAUNCH, goal, "--format", "json").stdout)
    assert as_json == [{"N": "/rover/pure_pursuit", "T": "/rover/base_waypoint"}]
    as_csv = archlog("query", BUGGY, *LAUNCH, "queue_size(P, S)", "--format", "csv").stdout
    assert as_csv.startswith("P,S\n") and "unbounded" in as_csv
    bad = archlog("query", BUGGY, *LAUNCH, "publisher(P, N, T)")
    assert bad.returncode == 2 and "publisher takes 4 columns, not 3" in bad.stderr
