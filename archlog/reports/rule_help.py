"""What a report says about a rule beyond its findings: the fix hint, the link, an example finding,
and the whole explanation `archlog rule ID` prints."""

from __future__ import annotations

import difflib
import re
from collections.abc import Mapping
from pathlib import Path

from archlog.rules.ruleset import BUILTIN, Rule

INFO_URI = "https://github.com/archlog/archlog"
DOCS_URI = f"{INFO_URI}/blob/main/docs/rules.md"


_PLACE = re.compile(r"\{(\w+)\}")


def names(rule: Rule, text: str, values: Mapping[str, object] | None = None) -> str:
    """`text` with each `{column}` of the rule replaced by the finding's value, or by the column's
    name in capitals without a finding; other braces stay as written."""
    def fill(match: re.Match) -> str:
        name = match.group(1)
        if values is not None and name in values:
            return str(values[name])
        return name.upper() if name in rule.columns else "" if name in rule.lists else match.group(0)

    return _PLACE.sub(fill, text)


def hint(rule: Rule, values: Mapping[str, object] | None = None) -> str:
    """The first paragraph of the rule's `help`, on one line, with the finding's own names."""
    return names(rule, " ".join(rule.help.split("\n\n")[0].split()), values)


def help_text(rule: Rule) -> str:
    """The rule's whole `help`, columns named in capitals (rule pages, SARIF)."""
    return names(rule, rule.help)


def url(rule: Rule) -> str:
    """The rule's `url`, else its section of docs/rules.md for a shipped rule, else nothing."""
    if rule.url:
        return rule.url
    return f"{DOCS_URI}#{rule.id.lower()}" if Path(rule.file).parent == BUILTIN else ""


def fixtures(rule: Rule) -> list[Path]:
    """The rule's fixture folders: tests/<stem> and tests/<stem>__<suffix> next to its file."""
    path = Path(rule.file)
    return sorted(p for p in (path.parent / "tests").glob(f"{path.stem}*")
                  if p.is_dir() and p.name.partition("__")[0] == path.stem)


def example(rule: Rule) -> str:
    """A finding of the rule as its first fixture expects it (`file:line subject: message`), or ''."""
    for case in fixtures(rule):
        expected = case / "findings.expected"
        lines = expected.read_text(encoding="utf-8").splitlines() if expected.is_file() else []
        for line in lines:
            if line.startswith(f"{rule.id} "):
                return line.removeprefix(f"{rule.id} ")
    return ""


def severity(rule: Rule) -> str:
    """The rule's severity, and when its findings are notes instead (`unsure`)."""
    if not rule.unsure:
        return rule.severity
    return f"{rule.severity}; a note when what archlog could not read may hold the counterpart"


def explain(rule: Rule) -> str:
    """Everything about a rule, as `archlog rule ID` prints it."""
    parts = [f"{rule.id} {rule.name} ({severity(rule)}, precision {rule.precision}"
             + (f"; tags: {', '.join(rule.tags)})" if rule.tags else ")"), "", rule.summary]
    if rule.description:
        parts += ["", rule.description]
    if example(rule):
        parts += ["", "Example finding (from the rule's fixtures):", f"  {example(rule)}"]
    if rule.help:
        parts += ["", "How to fix:", help_text(rule)]
    parts += ["", f"Finding: {rule.predicate}({', '.join(rule.columns)}); defined in {rule.file}:{rule.line}"]
    if url(rule):
        parts.append(f"More: {url(rule)}")
    return "\n".join(parts) + "\n"


def listing(rules: list[Rule]) -> str:
    """One line per rule: id, severity, name and summary."""
    return "".join(f"{r.id:<7} {r.severity:<8} {r.name}: {r.summary}\n" for r in rules)


def lookup(rules: list[Rule], key: str) -> str:
    """`explain` of the rules whose id or name is `key` (any case), else of those whose id starts
    with it; a LookupError with the nearest ids and names when none does."""
    found = [r for r in rules if key.lower() in (r.id.lower(), r.name.lower())] or \
        [r for r in rules if re.match(re.escape(key), r.id, re.I)]
    if not found:
        near = difflib.get_close_matches(key, [k for r in rules for k in (r.id, r.name)], n=3, cutoff=0.5)
        raise LookupError(f"no rule '{key}'" + (f"; did you mean {' or '.join(near)}?" if near else
                                                "; `archlog rule` lists them"))
    return "\n".join(explain(r) for r in found)
