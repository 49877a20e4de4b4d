"""Every corpus system yields exactly its expected findings; every clean twin yields none.
`pytest --update-goldens` rewrites the `findings` of a case.json that differs."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import CORPUS, CORPUS_BEHAVIOR, CORPUS_ROS2, corpus_cases, finding_keys, load_case, run_case
from support.goldens import rewrite_case_findings

CASES = corpus_cases(CORPUS) + corpus_cases(CORPUS_ROS2) + corpus_cases(CORPUS_BEHAVIOR)


@pytest.mark.parametrize(("corpus", "least"), [(CORPUS, 8), (CORPUS_ROS2, 6), (CORPUS_BEHAVIOR, 7)],
                         ids=["ros1", "ros2", "behavior"])
def test_corpus_has_buggy_and_clean_twins(corpus: Path, least: int) -> None:
    cases = {p.parent for p in corpus_cases(corpus)}
    assert len(cases) >= least
    for case in cases:
        assert (case / "buggy" / "case.json").is_file()
        assert (case / "clean" / "case.json").is_file()
        assert load_case(case / "buggy")["findings"], f"{case.name}/buggy expects no finding"
        assert load_case(case / "clean")["findings"] == []


@pytest.mark.parametrize("variant", CASES, ids=lambda p: f"{p.parent.parent.name}/{p.parent.name}/{p.name}")
def test_expected_findings(variant: Path, update_goldens: bool) -> None:
    analysis, findings = run_case(variant)
    expected = sorted((f["rule"], f["file"], f["line"], f["subject"]) for f in load_case(variant)["findings"])
    if update_goldens and finding_keys(findings) != expected:
        rewrite_case_findings(variant / "case.json", [dict(zip(("rule", "file", "line", "subject"), key))
                                                      for key in finding_keys(findings)])
        expected = finding_keys(findings)
    assert finding_keys(findings) == expected
    assert [d for d in analysis.diagnostics.items if d.severity == "error"] == []
    for finding in findings:
        assert finding.location.file and finding.location.line > 0
        assert all(r.file and r.line > 0 for r in finding.related)
