"""`archlog test-rules DIR`: run rule fixtures and compare with CodeQL-style .expected files.

DIR holds rule files (`*.lp`) and a `tests/` folder with one folder per case. A case is either a
fact file `facts.json` ({"relation": [[cell, ...], ...]}, an unknown cell written "?(expr)",
near-miss names and namespaces computed unless given) or a workspace with `case.json`
({"launch": [...], "args": {...}}). Its `findings.expected` lists one finding per line:
`RULE file:line subject: message`, sorted. A case folder is named after its rule file's stem:
`<stem>` for a case where the rule fires, `<stem>__clean` (the defect fixed) where it does not.
"""

from __future__ import annotations

import difflib
import json
import re
from pathlib import Path

from rich.console import Console
from rich.markup import escape

from archlog.analysis import analyse
from archlog.facts.namespaces import ADDED, add_namespaces
from archlog.facts.near_misses import add_near_names
from archlog.facts.parameters import add_param_near
from archlog.facts.patterns import add_name_fits
from archlog.facts.schema import BY_NAME
from archlog.facts.store import Cell, FactStore
from archlog.queries.session import Session
from archlog.queries.table import plural
from archlog.rules.engine import Engine, Finding, render
from archlog.rules.ruleset import BUILTIN, RuleError, RuleSet, load_rules
from archlog.values import Unknown

EXPECTED = "findings.expected"


class FixtureError(Exception):
    """A case file that cannot be used, with file:line."""

    def __init__(self, file: Path, line: int, message: str) -> None:
        super().__init__(f"{file}:{line}: {message}")


def run_rule_tests(folders: list[Path], update: bool, console: Console, only: bool = False) -> bool:
    """True when every rule of the folders loads and checks (as `check --rules` does) and every case
    matches its expected findings. With `only`, the findings of the shipped rules are left out when
    testing other folders (their relations stay usable)."""
    ok, count, written, rules = True, 0, 0, 0
    for folder in folders:
        own = folder.resolve() == BUILTIN
        try:
            ruleset = load_rules([] if own else [folder])
            Engine(ruleset)  # unknown relations, unsafe variables, findings no rule derives...
        except RuleError as exc:
            ok = False
            console.print(f"[red]FAIL[/] {escape(str(exc))}", highlight=False)
            continue
        rules += sum(own or Path(r.file).resolve().parent != BUILTIN for r in ruleset.rules)
        keep = {r.id for r in ruleset.rules if not only or own or Path(r.file).resolve().parent != BUILTIN}
        for case in sorted(p for p in (folder / "tests").glob("*") if p.is_dir()):
            count += 1
            try:
                found = [f for f in case_findings(case, ruleset) if f.rule.id in keep]
            except FixtureError as exc:
                ok = False
                console.print(f"[red]FAIL[/] {escape(str(case))}: {escape(str(exc))}", highlight=False)
                continue
            got = describe(found)
            expected_file = case / EXPECTED
            expected = expected_file.read_text() if expected_file.is_file() else ""
            if update and (got != expected or not expected_file.is_file()):
                expected_file.write_text(got)
                written += 1
                console.print(f"wrote {escape(str(expected_file))} ({plural(len(found), 'finding')})", highlight=False)
                expected = got
            if got == expected:
                console.print(f"[green]ok[/]   {escape(str(case))}")
                continue
            ok = False
            console.print(f"[red]FAIL[/] {escape(str(case))}")
            for line in difflib.unified_diff(expected.splitlines(), got.splitlines(), "expected", "got", lineterm=""):
                console.print(f"  {escape(line)}", highlight=False)
    updated = f"; {plural(written, 'file')} written" if update else ""
    verdict = "some failed" if not ok else "all passed" if count else "nothing tested"
    console.print(f"{plural(rules, 'rule')}, {plural(count, 'case')}, {verdict}{updated}")
    return ok


def case_findings(case: Path, ruleset: RuleSet) -> list[Finding]:
    if (case / "facts.json").is_file():
        store = load_facts(case / "facts.json")
    else:
        spec = _json(case / "case.json")
        if not isinstance(spec, dict) or not isinstance(spec.get("launch", []), list) or \
                not isinstance(spec.get("args", {}), dict):
            raise FixtureError(case / "case.json", 1, 'expected {"launch": [FILE, ...], "args": {NAME: VALUE}}')
        store = analyse([case], spec.get("launch", []), spec.get("args", {}), []).store
    return Session(store, ruleset).findings()


def _json(path: Path) -> object:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise FixtureError(path.parent, 0, "a case folder needs facts.json or case.json") from None
    except json.JSONDecodeError as exc:
        raise FixtureError(path, exc.lineno, f"not valid JSON: {exc.msg} (column {exc.colno})") from None


def load_facts(path: Path) -> FactStore:
    """A fact store from a case's facts.json; every problem is a FixtureError at its line."""
    data = _json(path)
    if not isinstance(data, dict):
        raise FixtureError(path, 1, 'expected an object {"relation": [[cell, ...], ...]}')
    text = path.read_text(encoding="utf-8")
    store = FactStore()
    for relation, rows in data.items():
        line = _line_of(text, relation)
        if relation not in BY_NAME:
            close = difflib.get_close_matches(relation, list(BY_NAME), 1, 0.7)
            hint = f"did you mean {close[0]}?" if close else "docs/facts.md lists the fact relations"
            raise FixtureError(path, line, f"unknown fact relation {relation!r} ({hint})")
        columns = BY_NAME[relation].columns
        if not isinstance(rows, list):
            raise FixtureError(path, line, f"{relation}: expected a list of rows")
        for number, row in enumerate(rows, 1):
            if not isinstance(row, list) or len(row) != len(columns) or \
                    not all(isinstance(c, (str, int)) and not isinstance(c, bool) for c in row):
                raise FixtureError(path, line, f"{relation} row {number}: expected {len(columns)} strings or integers "
                                   f"({', '.join(c.name for c in columns)}), got {json.dumps(row)}")
            store.add(relation, *(_cell(c, path) for c in row))
    if not set(ADDED) & set(data):
        add_namespaces(store)
    if "near_name" not in data:
        add_near_names(store, 0.5)
    if "param_near" not in data:
        add_param_near(store, 0.5)
    if "may_name" not in data:
        add_name_fits(store)
    return store


def _cell(value: str | int, path: Path) -> Cell:
    """A fixture cell; an unknown value is written ?(expr), as archlog writes it everywhere."""
    if isinstance(value, str) and value.startswith("?(") and value.endswith(")"):
        return Unknown(value[2:-1], path.name, 0)
    return value


def _line_of(text: str, key: str) -> int:
    found = re.search(rf'"{re.escape(key)}"\s*:', text)
    return text.count("\n", 0, found.start()) + 1 if found else 1


def describe(findings: list[Finding]) -> str:
    """One line per finding, sorted: `RULE file:line subject: message` (the rendered message);
    `RULE [note] ...` when the finding is a note of a rule of another severity (`unsure`)."""
    lines = sorted(f"{f.tag} {f.location.file}:{f.location.line} {render(next(iter(f.values.values())))}: "
                   f"{f.message}" for f in findings)
    return "".join(line + "\n" for line in lines)
