"""The house plan of the shipped rules: a rule file is named `{id}_{name}.lp` and its fixtures
`tests/{stem}` (positive) and `tests/{stem}__clean` (negative); helper relations stay in the file
that defines them unless they live in prelude.lp; every derived relation Python reads is declared
in the fact schema (docs/facts.md)."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest
from conftest import ROOT

from archlog.facts.schema import BY_NAME, DERIVED, DERIVED_BY_NAME
from archlog.facts.store import FactStore
from archlog.rules.engine import Engine, _parse
from archlog.rules.ruleset import BUILTIN, RuleSet, load_rules

RULE_FOLDERS = [BUILTIN, ROOT / "docs" / "examples" / "rules"]


def stem(rule) -> str:
    return f"{rule.id}_{rule.name.replace('-', '_')}"


def rules_of(folder: Path) -> list:
    ruleset = RuleSet()
    for path in sorted(folder.glob("*.lp")):
        ruleset.add_file(path)
    return ruleset.rules


@pytest.mark.parametrize("folder", RULE_FOLDERS, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_rule_file_stem_is_id_and_name(folder: Path) -> None:
    rules = rules_of(folder)
    assert rules
    for rule in rules:
        assert Path(rule.file).stem == stem(rule), f"{rule.file}: expected {stem(rule)}.lp"
    assert len({r.file for r in rules}) == len(rules), "one rule per file"


@pytest.mark.parametrize("folder", RULE_FOLDERS, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_fixture_folders_are_named_after_their_rule(folder: Path) -> None:
    """Every fixture folder is `<stem>` or `<stem>__<suffix>`; every rule has a positive fixture
    (its expected file lists a finding of the rule) and a negative one, `<stem>__clean`, whose
    expected file lists none of the rule's findings."""
    stems = {stem(r): r for r in rules_of(folder)}
    kinds: dict[str, set[str]] = {s: set() for s in stems}
    for case in sorted(p for p in (folder / "tests").iterdir() if p.is_dir()):
        base, _sep, suffix = case.name.partition("__")
        assert base in stems, f"{case.name} names no rule file (expected <stem> or <stem>__<suffix>)"
        rule_lines = [line for line in (case / "findings.expected").read_text().splitlines()
                      if line.split(" ", 1)[0] == stems[base].id]
        if suffix.startswith("clean"):
            assert rule_lines == [], f"{case.name} is a negative fixture but expects {rule_lines}"
            kinds[base].add("negative")
        else:
            assert rule_lines, f"{case.name} expects no {stems[base].id} finding (name it {base}__clean...)"
            kinds[base].add("positive")
    assert {s: k for s, k in kinds.items() if k != {"positive", "negative"}} == {}


def test_helper_relations_stay_in_their_rule_file() -> None:
    """A relation that a shipped rule file defines is used by no other rule file, unless it is
    the rule's finding (documented in rules.md); shared relations live in prelude.lp."""
    ruleset = load_rules([])
    findings = {(r.predicate, len(r.columns)) for r in ruleset.rules}
    defined: dict[tuple[str, int], set[str]] = {}
    used: dict[tuple[str, int], set[str]] = {}
    for program in ruleset.programs:
        parsed = _parse(program)
        for sig in parsed.heads:
            defined.setdefault(sig, set()).add(Path(program.file).name)
        for sig, _pos in parsed.body:
            used.setdefault(sig, set()).add(Path(program.file).name)
    shared = {sig: sorted(used.get(sig, set()) - files) for sig, files in defined.items()
              if "prelude.lp" not in files and sig not in findings and used.get(sig, set()) - files}
    assert shared == {}, "move these to prelude.lp"
    assert [sig for sig, files in defined.items() if len(files) > 1] == []


def test_declared_derived_relations_are_derived_where_documented() -> None:
    ruleset = load_rules([])
    heads = {}
    for program in ruleset.programs:
        for sig in _parse(program)[0]:
            heads.setdefault(sig, Path(program.file).name)
    for rel in DERIVED:
        assert heads.get((rel.name, rel.arity)) == rel.source, f"{rel.name}/{rel.arity} is not derived in {rel.source}"
        assert rel.name not in BY_NAME


_GOAL_RELATION = re.compile(r"(?<![\w\"'])([a-z]\w*)\s*\(")


def relations_read_by_python() -> dict[tuple[str, int | None], str]:
    """(relation, arity or None) -> where: relations Python asks the grounded program for by name
    (`by_signature("x", n)`, query goals, lists of goals), in archlog/, tests/ and bench/."""
    found: dict[tuple[str, int | None], str] = {}
    for path in sorted(p for folder in ("archlog", "tests", "bench") for p in (ROOT / folder).rglob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        for node in ast.walk(tree):
            where = f"{path.relative_to(ROOT)}:{getattr(node, 'lineno', 0)}"
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.args \
                    and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str):
                if node.func.attr == "by_signature" and re.fullmatch(r"[a-z]\w*", node.args[0].value):
                    second = node.args[1] if len(node.args) > 1 else None
                    arity = second.value if isinstance(second, ast.Constant) else None
                    found[(node.args[0].value, arity)] = where
                elif node.func.attr == "query":
                    found.update({(name, None): where for name in _GOAL_RELATION.findall(node.args[0].value)})
            elif isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "GOALS"
                                                      for t in node.targets):
                for item in ast.walk(node.value):
                    if isinstance(item, ast.Constant) and isinstance(item.value, str):
                        found.update({(name, None): where for name in _GOAL_RELATION.findall(item.value)})
    return found


def test_derived_relations_read_by_python_are_declared() -> None:
    ruleset = load_rules([])
    findings = {r.predicate: len(r.columns) for r in ruleset.rules}
    arity = {**{r.name: r.arity for r in BY_NAME.values()}, **{r.name: r.arity for r in DERIVED}, **findings}
    read = relations_read_by_python()
    assert ("required_topic", 2) in read  # reports/behavior.py
    for rule in ruleset.rules:
        read.update({(relation, 2): f"{rule.file} lists" for relation, _column in rule.lists.values()})
    undeclared = {f"{name}/{n}": where for (name, n), where in read.items()
                  if name not in arity or (n is not None and arity[name] != n)}
    assert undeclared == {}, "declare them in archlog/facts/schema.py (DERIVED)"
    assert set(DERIVED_BY_NAME) >= {name for name, _n in read if name not in BY_NAME and name not in findings}


def test_derived_relations_python_reads_directly_are_grounded_at_once() -> None:
    """The rules of a derived relation no rule reads wait until a query names it (rules/loading.py):
    Python that reads the grounded program directly (`by_signature`) must find its atoms there."""
    later = Engine(load_rules([])).start(FactStore()).later
    read = {name for name, arity in relations_read_by_python() if arity is not None and name not in BY_NAME}
    assert "required_topic" in read and not read & set(later)
