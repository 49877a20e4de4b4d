"""Differential test: archlog's launch interpretation equals roslaunch's own config loader."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import ROOT, corpus_cases, load_case, requires_ros
from support.launch_oracle import archlog_view, case_args, expected_error_lines, roslaunch_view

pytestmark = requires_ros()

CASES = sorted(p for p in (ROOT / "corpus" / "launch").iterdir() if (p / "main.launch").is_file())
PACKAGES = ROOT / "corpus" / "launch" / "_pkgs"


def test_enough_cases() -> None:
    assert len(CASES) >= 40


@pytest.mark.parametrize("case", CASES, ids=lambda p: p.name)
def test_launch_case_agrees_with_roslaunch(case: Path) -> None:
    files = [case / "main.launch"]
    args = case_args(files[0])
    theirs = roslaunch_view(files, args, [case, PACKAGES])
    ours = archlog_view(files, args, [case, PACKAGES])
    marks = expected_error_lines(sorted(case.glob("*.launch")))
    if theirs.error:
        assert marks, f"roslaunch rejects this case ({theirs.error}); mark the element with <!-- roslaunch-error -->"
        found = {(Path(d.file).name, d.line) for d in ours.diagnostics
                 if d.severity == "error" or d.code in ("launch-unresolved", "launch-condition")}
        assert ours.error and set(marks) <= found | (set(marks) if ours.error == "duplicate node names"
                                                     else set()), (theirs.error, ours.diagnostics)
        return
    assert not marks, "case is marked as an error but roslaunch accepts it"
    assert ours.error is None, ours.diagnostics
    assert ours.nodes == theirs.nodes
    assert ours.params == theirs.params


@pytest.mark.parametrize("variant", corpus_cases(), ids=lambda p: f"{p.parent.name}/{p.name}")
def test_corpus_systems_agree_with_roslaunch(variant: Path) -> None:
    from archlog.analysis import resolve_launch
    from archlog.diagnostics import DiagnosticSink
    from archlog.extract.workspace.index import Workspace

    case = load_case(variant)
    files = [resolve_launch(spec, Workspace([variant], DiagnosticSink())) for spec in case["launch"]]
    theirs = roslaunch_view(files, case.get("args", {}), [variant / "src"])
    ours = archlog_view(files, case.get("args", {}), [variant])
    if theirs.error:
        assert ours.error, theirs.error
        return
    assert (ours.nodes, ours.params) == (theirs.nodes, theirs.params)
