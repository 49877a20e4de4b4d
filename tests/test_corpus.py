"""Every corpus system yields exactly its expected findings; every clean twin yields none."""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import CORPUS, corpus_cases, finding_keys, load_case, run_case

CASES = corpus_cases()


def test_corpus_has_buggy_and_clean_twins() -> None:
    names = {p.parent.name for p in CASES}
    assert len(names) >= 8
    for name in names:
        assert (CORPUS / name / "buggy" / "case.json").is_file()
        assert (CORPUS / name / "clean" / "case.json").is_file()
        assert load_case(CORPUS / name / "buggy")["findings"], f"{name}/buggy expects no finding"
        assert load_case(CORPUS / name / "clean")["findings"] == []


@pytest.mark.parametrize("variant", CASES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_expected_findings(variant: Path) -> None:
    analysis, findings = run_case(variant)
    expected = sorted((f["rule"], f["file"], f["line"], f["subject"]) for f in load_case(variant)["findings"])
    assert finding_keys(findings) == expected
    assert [d for d in analysis.diagnostics.items if d.severity == "error"] == []
    for finding in findings:
        assert finding.location.file and finding.location.line > 0
        assert all(r.file and r.line > 0 for r in finding.related)
