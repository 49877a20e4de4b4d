"""rospy/rclpy extraction on corpus/python fixtures, compared with their .expected files.

Set ARCHLOG_UPDATE_EXPECTED=1 to rewrite the .expected files (then review the diff)."""

from __future__ import annotations

import difflib
import os
from pathlib import Path

import pytest

from archlog.diagnostics import DiagnosticSink
from archlog.extract.python import extract_python
from conftest import ROOT
from support.describe import describe

FIXTURES = sorted(p for p in (ROOT / "corpus" / "python").iterdir() if p.suffix != ".expected")


def test_enough_fixtures() -> None:
    assert sum(p.name.startswith("rclpy_") for p in FIXTURES) >= 10
    assert sum(p.name.startswith("rospy_") for p in FIXTURES) >= 4


@pytest.mark.parametrize("fixture", FIXTURES, ids=lambda p: p.name)
def test_fixture_matches_expected(fixture: Path) -> None:
    sink = DiagnosticSink()
    got = describe(extract_python(fixture, "fixtures", fixture.name, fixture.name, sink), sink.items)
    expected_file = fixture.with_name(fixture.name + ".expected")
    if os.environ.get("ARCHLOG_UPDATE_EXPECTED"):
        expected_file.write_text(got)
    expected = expected_file.read_text() if expected_file.is_file() else ""
    diff = "".join(difflib.unified_diff(expected.splitlines(True), got.splitlines(True), "expected", "got"))
    assert not diff, diff
