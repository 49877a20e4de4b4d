"""Diagnostic codes are registered once (archlog.diagnostics.CODES), documented, and used (issue 16)."""

from __future__ import annotations

import ast
from collections import Counter
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


def test_codes_are_selected_ignored_and_rated_in_the_configuration(tmp_path: Path) -> None:
    from archlog.config import load_config

    items = [Diagnostic("a.launch", 1, "launch-process", "x", "note"), Diagnostic("a.launch", 2, "launch-tag", "y"),
             Diagnostic("b.py", 3, "python2", "z", "note")]
    (tmp_path / "archlog.toml").write_text('select = ["AL1"]\nignore = ["launch-process"]\n'
                                           '[severity]\npython2 = "error"\n')
    config = load_config(tmp_path / "archlog.toml", None)
    shown = [(d.code, d.severity) for d in config.diagnostics(items)]
    assert shown == [("launch-tag", "warning"), ("python2", "error")]
    assert config.select == ["AL1"]  # a rule pattern selects rules only: every diagnostic is still shown
    (tmp_path / "archlog.toml").write_text('select = ["launch-"]\n')
    assert [d.code for d in load_config(tmp_path / "archlog.toml", None).diagnostics(items)] == \
        ["launch-process", "launch-tag"]


def test_no_code_is_registered_twice() -> None:
    """CODES merges one table per group: a code written in two tables would silently keep only the last."""
    tree = ast.parse((PACKAGE / "diagnostics.py").read_text())
    tables = [node.args[1] for node in ast.walk(tree) if isinstance(node, ast.Call)
              and getattr(node.func, "id", "") == "_codes" and isinstance(node.args[1], ast.Dict)]
    written = Counter(key.value for table in tables for key in table.keys if isinstance(key, ast.Constant))
    assert sum(written.values()) == len(CODES) and [c for c, n in written.items() if n > 1] == []
