"""The one update switch of the suite, `pytest --update-goldens`, and its helpers (support/goldens.py)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT
from support.goldens import compare_text, rewrite_case_findings

FOUND = [{"rule": "AL102", "file": "src/a.cpp", "line": 4, "subject": "/x"},
         {"rule": "AL104", "file": "src/b.py", "line": 9, "subject": "/y"}]


def test_the_switch_is_off_unless_given(update_goldens: bool) -> None:
    assert update_goldens is False
    result = subprocess.run([sys.executable, "-m", "pytest", "--help", "-p", "no:cacheprovider"], capture_output=True,
                            text=True, cwd=ROOT, timeout=120)
    assert "--update-goldens" in result.stdout


def test_compare_text_rewrites_only_on_update(tmp_path: Path) -> None:
    golden = tmp_path / "x.expected"
    golden.write_text("a\n")
    assert "-a" in compare_text(golden, "b\n", update=False) and golden.read_text() == "a\n"
    assert compare_text(golden, "b\n", update=True) == "" and golden.read_text() == "b\n"
    assert compare_text(tmp_path / "new.expected", "c\n", update=True) == ""
    assert (tmp_path / "new.expected").read_text() == "c\n"


@pytest.mark.parametrize("findings_text", [
    '[\n    {\n      "rule": "AL101",\n      "file": "f",\n      "line": 1,\n      "subject": "/z"\n    }\n  ]',
    '[\n    {"rule": "AL101", "file": "f", "line": 1, "subject": "/z"}\n  ]',
    "[]",
], ids=["indented", "one-per-line", "empty"])
def test_case_findings_are_replaced_in_place(tmp_path: Path, findings_text: str) -> None:
    case = tmp_path / "case.json"
    head = '{\n  "launch": ["p/launch/x.launch"],\n  "description": "kept as written",\n'
    case.write_text(f'{head}  "findings": {findings_text},\n  "runtime": true\n}}\n')
    for findings in (FOUND, []):
        rewrite_case_findings(case, findings)
        text = case.read_text()
        assert text.startswith(head) and text.endswith('  "runtime": true\n}\n')
        assert json.loads(text)["findings"] == findings
    rewrite_case_findings(case, FOUND)
    assert json.loads(case.read_text())["findings"] == FOUND
