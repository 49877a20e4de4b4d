"""Code review workflows end to end on copies of corpus systems: --new-only against a git revision,
baselines that say what they wrote and hid, strict [[suppress]] entries, suppressions on a node's
launch element, and the concise summary line."""

from __future__ import annotations

import io
import json
import shutil
import subprocess
import sys
from pathlib import Path

from conftest import CORPUS

TYPO = CORPUS / "topic_typo" / "buggy"
CHECK = ["check", "src", "--launch", "waypoint_nav/launch/follow_waypoints.launch"]
LAUNCH = "src/waypoint_nav/launch/follow_waypoints.launch"


def archlog(*args: str | Path, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, timeout=300)


def git(repo: Path, *args: str) -> None:
    subprocess.run(["git", "-C", str(repo), "-c", "user.email=t@example.com", "-c", "user.name=t", *args],
                   check=True, capture_output=True, timeout=60)


def workspace(tmp: Path) -> Path:
    root = tmp / "repo"
    shutil.copytree(TYPO / "src", root / "src")
    return root


def test_new_only_reports_what_the_change_introduces(tmp_path: Path) -> None:
    repo = workspace(tmp_path)
    git(repo, "init", "-q")
    git(repo, "add", "-A")
    git(repo, "commit", "-qm", "base: one near miss")
    launch = repo / LAUNCH
    text = launch.read_text()
    # the change moves every line (the old finding moves too) and adds a second node named waypoint_loader
    text = text.replace("<launch>", "<launch>\n  <!-- a comment -->\n  <!-- another -->", 1)
    text = text.replace("  </group>", '    <node pkg="waypoint_nav" type="waypoint_loader.py" name="waypoint_loader"/>\n'
                        "  </group>", 1)
    launch.write_text(text)
    everything = json.loads(archlog(*CHECK, "--format", "json", "--fail-on", "never", cwd=repo).stdout)
    assert sorted(f["rule"] for f in everything["findings"]) == ["AL102", "AL301"]
    result = archlog(*CHECK, "--new-only", "--base", "HEAD", "--format", "json", cwd=repo)
    assert result.returncode == 1, result.stderr  # the new finding is an error
    report = json.loads(result.stdout)
    assert [f["rule"] for f in report["findings"]] == ["AL301"]
    assert report["hidden"] == {"pre-existing in HEAD": 1}
    text_report = archlog(*CHECK, "--new-only", cwd=repo).stdout
    assert "1 finding (1 error, 0 warnings, 0 notes); 1 pre-existing in HEAD not shown" in text_report
    bad = archlog(*CHECK, "--new-only", "--base", "no-such-ref", cwd=repo)
    assert bad.returncode == 2 and "--base no-such-ref: git archive failed" in bad.stderr


def test_baseline_says_what_it_wrote_hid_and_no_longer_matches(tmp_path: Path) -> None:
    repo = workspace(tmp_path)
    baseline = tmp_path / "baseline.json"
    written = archlog(*CHECK, "--write-baseline", baseline, cwd=repo)
    assert written.returncode == 0 and f"archlog: wrote 1 finding to {baseline}" in written.stderr
    hidden = archlog(*CHECK, "--baseline", baseline, cwd=repo)
    assert hidden.returncode == 0 and "0 findings (0 errors, 0 warnings, 0 notes); 1 in the baseline not shown" \
        in hidden.stdout
    assert archlog(*CHECK, "--fix", cwd=repo).returncode == 0  # the finding is fixed: its entry is stale
    stale = json.loads(archlog(*CHECK, "--baseline", baseline, "--format", "json", cwd=repo).stdout)
    entries = [d for d in stale["diagnostics"] if d["code"] == "stale-baseline"]
    assert len(entries) == 1 and entries[0]["line"] == 5 and entries[0]["file"].endswith("baseline.json")


def test_suppress_entries_are_strict_and_reported_when_unused(tmp_path: Path) -> None:
    repo = workspace(tmp_path)
    config = repo / "archlog.toml"
    config.write_text('[[suppress]]\nrule = "AL102"\nreason = "known"\n\n[[suppress]]\nnodes = "/rover/*"\n')
    wrong = archlog(*CHECK, cwd=repo)
    assert wrong.returncode == 2
    assert f"{config}:6: [[suppress]] has an unknown key 'nodes'" in wrong.stderr and "did you mean 'node'?" in wrong.stderr
    config.write_text('[[suppress]]\nrule = "AL102"\nreason = "known"\n\n[[suppress]]\nrule = "AL9*"\n')
    report = json.loads(archlog(*CHECK, "--format", "json", cwd=repo).stdout)
    assert report["findings"][0]["suppressed"] == {"kind": "external", "justification": "known"}
    unused = [d for d in report["diagnostics"] if d["code"] == "unused-suppression"]
    assert [(d["file"], d["line"]) for d in unused] == [("archlog.toml", 5)]
    config.write_text('[[suppress]]\nreason = "all of it"\n')
    assert "names no rule, node, topic or service" in archlog(*CHECK, cwd=repo).stderr


def test_a_comment_on_the_node_element_suppresses_findings_about_it(tmp_path: Path) -> None:
    repo = workspace(tmp_path)
    launch = repo / LAUNCH
    launch.write_text(launch.read_text().replace(
        '    <node pkg="waypoint_nav" type="pure_pursuit"',
        '    <!-- archlog: ignore[AL102] the planner topic is renamed next release -->\n'
        '    <node pkg="waypoint_nav" type="pure_pursuit"', 1))
    report = json.loads(archlog(*CHECK, "--format", "json", cwd=repo).stdout)
    (finding,) = report["findings"]
    assert finding["locations"][0]["file"].endswith(".cpp")  # located in the node's source, not the launch file
    assert finding["suppressed"]["justification"] == "the planner topic is renamed next release"
    assert not [d for d in report["diagnostics"] if d["code"] == "unused-suppression"]


def test_concise_ends_with_one_summary_line(tmp_path: Path) -> None:
    lines = archlog(*CHECK, "--format", "concise", cwd=workspace(tmp_path)).stdout.splitlines()
    assert len(lines) == 2 and " AL102 " in lines[0]
    assert lines[1] == "1 finding (1 error, 0 warnings, 0 notes); 0 diagnostics; 3 of 3 nodes fully recovered"


def test_github_annotations_and_junit(tmp_path: Path) -> None:
    import xml.etree.ElementTree as ET

    repo = workspace(tmp_path)
    github = archlog(*CHECK, "--format", "github", cwd=repo)
    assert github.returncode == 1
    first, summary = github.stdout.splitlines()
    assert first.startswith("::error file=src/waypoint_nav/src/pure_pursuit.cpp,line=45,col=")
    assert ",title=AL102 near-miss-topic::/rover/pure_pursuit subscribes to /rover/base_waypoint" in first
    assert summary.startswith("archlog: 1 finding (1 error")
    suite = ET.fromstring(archlog(*CHECK, "--format", "junit", cwd=repo).stdout).find("testsuite")
    assert suite is not None and (suite.get("tests"), suite.get("failures")) == ("1", "1")
    case = suite.find("testcase")
    assert case is not None and case.get("name") == "src/waypoint_nav/src/pure_pursuit.cpp:45"
    assert case.find("failure") is not None
    fixed = archlog(*CHECK, "--fix", "--format", "junit", cwd=repo)
    clean = ET.fromstring(fixed.stdout).find("testsuite")
    assert fixed.returncode == 0 and clean is not None and (clean.get("tests"), clean.get("failures")) == ("1", "0")


def test_repeated_notes_of_one_code_are_counted_not_listed(tmp_path: Path) -> None:
    from rich.console import Console

    from archlog.diagnostics import Diagnostic
    from archlog.reports.report import Report
    from archlog.reports.text import print_text

    notes = [Diagnostic("a.launch", n, "env-not-given", f"environment variable V{n} is not given", "note")
             for n in range(1, 11)]
    warning = Diagnostic("a.launch", 20, "launch-unresolved", "<include> skipped", "warning")
    out = io.StringIO()
    console = Console(file=out, no_color=True, width=200)
    print_text(Report([], [*notes, warning], [], tmp_path), console)
    text = out.getvalue()
    assert text.count("env-not-given") == 4 and "<include> skipped" in text
    assert "... and 7 more env-not-given notes like these" in text
    assert "0 findings (0 errors, 0 warnings, 0 notes); 11 diagnostics" in text
