"""Diagnostic codes are registered once (archlog.diagnostics.CODES), documented, and used (issue 16)."""

from __future__ import annotations

from pathlib import Path

import pytest

from archlog.diagnostics import CODES, SEVERITIES, Diagnostic, DiagnosticSink

PACKAGE = Path(__file__).resolve().parent.parent / "archlog"


def test_an_unregistered_code_is_refused() -> None:
    with pytest.raises(ValueError, match="unregistered diagnostic code 'no-such-code'"):
        DiagnosticSink().add("a.launch", 3, "no-such-code", "text")
    with pytest.raises(ValueError):
        Diagnostic("a.launch", 3, "no-such-code", "text")


def test_a_diagnostic_without_severity_takes_the_registered_one() -> None:
    sink = DiagnosticSink()
    sink.add("a.launch", 3, "launch-arg-unknown", "arg 'x' is not known statically")
    assert sink.items[0].severity == CODES["launch-arg-unknown"].severity == "note"


def test_every_registered_code_is_emitted_somewhere() -> None:
    sources = "".join(p.read_text() for p in PACKAGE.rglob("*.py") if p.name != "diagnostics.py")
    unused = [code for code in CODES if f'"{code}"' not in sources]
    assert unused == []


def test_registry_entries_are_complete() -> None:
    for code, entry in CODES.items():
        assert entry.severity in SEVERITIES, code
        assert entry.meaning.endswith(".") and entry.help, code
