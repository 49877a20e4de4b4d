"""Inline and configured suppressions, unused suppressions, and baselines robust to line moves."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import jsonschema
from conftest import CORPUS, ROOT

LAUNCH = ["--launch", "waypoint_nav/launch/follow_waypoints.launch"]
CPP = Path("src/waypoint_nav/src/pure_pursuit.cpp")
SCHEMA = json.loads((ROOT / "archlog" / "reports" / "findings.schema.json").read_text())


def copy_case(tmp_path: Path) -> Path:
    target = tmp_path / "ws"
    shutil.copytree(CORPUS / "topic_typo" / "buggy", target)
    return target


def check(workspace: Path, *extra: str | Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", "check", str(workspace), *LAUNCH, *map(str, extra)],
                          capture_output=True, text=True, cwd=ROOT, timeout=300)


def insert_line(path: Path, line: int, text: str) -> None:
    lines = path.read_text().splitlines(keepends=True)
    lines.insert(line - 1, text + "\n")
    path.write_text("".join(lines))


def test_inline_suppression_in_cpp_marks_the_finding(tmp_path: Path, sarif_schema: dict) -> None:
    ws = copy_case(tmp_path)
    insert_line(ws / CPP, 45, "  // archlog: ignore[AL102] the planner topic is renamed at deployment")
    assert check(ws).returncode == 0
    document = json.loads(check(ws, "--format", "json").stdout)
    jsonschema.validate(document, SCHEMA)
    [finding] = document["findings"]
    assert finding["suppressed"] == {"kind": "inSource", "justification": "the planner topic is renamed at deployment"}
    assert document["summary"]["error"] == 0
    sarif = json.loads(check(ws, "--format", "sarif").stdout)
    jsonschema.validate(sarif, sarif_schema)
    assert sarif["runs"][0]["results"][0]["suppressions"][0]["kind"] == "inSource"
    assert "1 suppressed" in check(ws).stdout


def test_unused_suppression_is_reported(tmp_path: Path) -> None:
    ws = copy_case(tmp_path)
    insert_line(ws / CPP, 10, "// archlog: ignore[AL101] nothing to suppress here")
    diags = json.loads(check(ws, "--format", "json").stdout)["diagnostics"]
    assert [(d["code"], d["file"], d["line"]) for d in diags] == [("unused-suppression", str(CPP), 10)]


def test_configured_suppression_by_topic_glob(tmp_path: Path) -> None:
    ws = copy_case(tmp_path)
    (ws / "archlog.toml").write_text('[[suppress]]\nrule = "AL102"\ntopic = "/rover/*"\nreason = "accepted"\n')
    [finding] = json.loads(check(ws, "--format", "json").stdout)["findings"]
    assert finding["suppressed"] == {"kind": "external", "justification": "accepted"}
    (ws / "archlog.toml").write_text('[[suppress]]\nrule = "AL102"\ntopic = "/other/*"\n')
    assert "suppressed" not in json.loads(check(ws, "--format", "json").stdout)["findings"][0]


def test_baseline_survives_unrelated_line_moves(tmp_path: Path) -> None:
    ws = copy_case(tmp_path)
    baseline = tmp_path / "baseline.json"
    written = check(ws, "--write-baseline", baseline)
    assert written.returncode == 0 and f"archlog: wrote 1 finding to {baseline}" in written.stderr
    assert len(json.loads(baseline.read_text())["findings"]) == 1
    insert_line(ws / CPP, 3, "// a new comment moves every line below")
    insert_line(ws / CPP, 3, "#include <cmath>")
    result = check(ws, "--baseline", baseline, "--format", "json")
    assert result.returncode == 0 and json.loads(result.stdout)["findings"] == []
    assert check(ws, "--baseline", tmp_path / "missing.json").returncode == 2


def test_codequality_report_and_ci_files(tmp_path: Path) -> None:
    import yaml

    ws = copy_case(tmp_path)
    [issue] = json.loads(check(ws, "--format", "codequality").stdout)
    assert issue["location"] == {"path": str(CPP), "lines": {"begin": 45}} and issue["severity"] == "major"
    for name in ("docs/ci/github-actions.yml", "docs/ci/gitlab-ci.yml", ".pre-commit-hooks.yaml"):
        assert yaml.safe_load((ROOT / name).read_text())


def test_inline_suppression_in_launch_xml(tmp_path: Path) -> None:
    ws = tmp_path / "ws"
    shutil.copytree(CORPUS / "unused_remap_duplicate" / "buggy", ws)
    launch = ws / "src" / "scout_bringup" / "launch" / "sensors.launch"
    insert_line(launch, 13, "    <!-- archlog: ignore[unused-remap] kept for the old driver -->")
    spec = json.loads((ws / "case.json").read_text())["launch"]
    result = subprocess.run([sys.executable, "-m", "archlog", "check", str(ws), "--launch", spec[0], "--format",
                             "json", "--fail-on", "never"], capture_output=True, text=True, cwd=ROOT, timeout=300)
    suppressed = [f for f in json.loads(result.stdout)["findings"] if "suppressed" in f]
    assert [(f["rule"], f["suppressed"]["justification"]) for f in suppressed] == [("AL401", "kept for the old driver")]
