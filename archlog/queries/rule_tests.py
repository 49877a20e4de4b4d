"""`archlog test-rules DIR`: run rule fixtures and compare with CodeQL-style .expected files.

DIR holds rule files (`*.lp`) and a `tests/` folder with one folder per case. A case is either a
fact file `facts.json` ({"relation": [[cell, ...], ...]}, an unknown cell as {"unknown": "expr"},
near-miss names computed unless given) or a workspace with `case.json` ({"launch": [...],
"args": {...}}). Its `findings.expected` lists one finding per line:
`RULE file:line subject: message`, sorted. A case folder is named after its rule file's stem:
`<stem>` for a case where the rule fires, `<stem>__clean` (the defect fixed) where it does not.
"""

from __future__ import annotations

import difflib
import json
from pathlib import Path

from rich.console import Console
from rich.markup import escape

from archlog.analysis import analyse
from archlog.facts.compose import add_near_names
from archlog.facts.store import FactStore
from archlog.queries.session import Session
from archlog.rules.engine import Finding, render
from archlog.rules.ruleset import BUILTIN, load_rules
from archlog.values import Unknown

EXPECTED = "findings.expected"


def run_rule_tests(folders: list[Path], update: bool, console: Console) -> bool:
    """True when every case matches its expected findings."""
    ok, count = True, 0
    for folder in folders:
        ruleset = load_rules([] if folder.resolve() == BUILTIN else [folder])
        for case in sorted(p for p in (folder / "tests").glob("*") if p.is_dir()):
            count += 1
            got = describe(case_findings(case, ruleset))
            expected_file = case / EXPECTED
            expected = expected_file.read_text() if expected_file.is_file() else ""
            if update and got != expected:
                expected_file.write_text(got)
                console.print(f"wrote {escape(str(expected_file))}", highlight=False)
                expected = got
            if got == expected:
                console.print(f"[green]ok[/]   {escape(str(case))}")
                continue
            ok = False
            console.print(f"[red]FAIL[/] {escape(str(case))}")
            for line in difflib.unified_diff(expected.splitlines(), got.splitlines(), "expected", "got", lineterm=""):
                console.print(f"  {escape(line)}", highlight=False)
    console.print(f"{count} case{'s' if count != 1 else ''}, {'all passed' if ok else 'some failed'}")
    return ok


def case_findings(case: Path, ruleset) -> list[Finding]:
    if (case / "facts.json").is_file():
        store = load_facts(case / "facts.json")
    else:
        spec = json.loads((case / "case.json").read_text())
        store = analyse([case], spec.get("launch", []), spec.get("args", {}), []).store
    return Session(store, ruleset).findings()


def load_facts(path: Path) -> FactStore:
    data = json.loads(path.read_text())
    store = FactStore()
    for relation, rows in data.items():
        for row in rows:
            store.add(relation, *(Unknown(c["unknown"], path.name, 0) if isinstance(c, dict) else c for c in row))
    if "near_name" not in data:
        add_near_names(store, 0.5)
    return store


def describe(findings: list[Finding]) -> str:
    """One line per finding, sorted: `RULE file:line subject: message` (the rendered message)."""
    lines = sorted(f"{f.rule.id} {f.location.file}:{f.location.line} {render(next(iter(f.values.values())))}: "
                   f"{f.message}" for f in findings)
    return "".join(line + "\n" for line in lines)
