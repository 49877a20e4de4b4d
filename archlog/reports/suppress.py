"""Suppressions and baselines.

Inline: `<!-- archlog: ignore[AL401] reason -->` (launch XML), `// archlog: ignore[AL102] reason`
(C++) or `# archlog: ignore[AL102] reason` (Python) on the finding's line or the line above.
Configured: `[[suppress]]` tables in archlog.toml with `rule`, `node` and/or `topic` globs and a
`reason`. A suppressed finding stays in the report, marked; an inline suppression that matches
nothing is reported. A baseline file holds the fingerprints of accepted findings.
"""

from __future__ import annotations

import fnmatch
import json
import re
from dataclasses import dataclass
from pathlib import Path

from archlog import sandbox
from archlog.diagnostics import Diagnostic
from archlog.rules.engine import Finding

MARKER = re.compile(r"archlog:\s*ignore\[([\w\s,.-]+)\]\s*(.*?)\s*(?:-->)?\s*$")
BASELINE_VERSION = 1


@dataclass(frozen=True)
class Inline:
    file: str
    line: int
    rules: tuple[str, ...]
    reason: str


def inline_suppressions(files: set[str], root: Path) -> dict[tuple[str, int], Inline]:
    """Every inline suppression in the given files (paths as the findings show them)."""
    found: dict[tuple[str, int], Inline] = {}
    for file in sorted(files):
        path = Path(file) if Path(file).is_absolute() else root / file
        try:
            lines = sandbox.read_text(path, "source").splitlines()
        except sandbox.Refused:
            continue
        for number, text in enumerate(lines, 1):
            match = MARKER.search(text)
            if match:
                rules = tuple(r.strip() for r in match.group(1).split(",") if r.strip())
                found[(file, number)] = Inline(file, number, rules, match.group(2).strip())
    return found


def apply_suppressions(findings: list[Finding], files: set[str], root: Path,
                       configured: list[dict]) -> list[Diagnostic]:
    """Mark suppressed findings; returns a diagnostic for each inline suppression left unused."""
    inline = inline_suppressions(files, root)
    used: set[tuple[str, int]] = set()
    for finding in findings:
        loc = finding.location
        for line in (loc.line, loc.line - 1):
            mark = inline.get((loc.file, line))
            if mark and (finding.rule.id in mark.rules or finding.rule.name in mark.rules):
                finding.suppression = ("inSource", mark.reason or "suppressed in source")
                used.add((mark.file, mark.line))
                break
        if finding.suppression is None:
            entry = next((e for e in configured if _matches(e, finding)), None)
            if entry is not None:
                finding.suppression = ("external", str(entry.get("reason", "suppressed in the configuration")))
    return [Diagnostic(mark.file, mark.line, "unused-suppression",
                       f"suppression of {', '.join(mark.rules)} matches no finding here; remove it", "warning")
            for key, mark in sorted(inline.items()) if key not in used]


def _matches(entry: dict, finding: Finding) -> bool:
    checks = {"rule": [finding.rule.id, finding.rule.name], "node": finding.subjects.get("nodes", []),
              "topic": finding.subjects.get("topics", []), "service": finding.subjects.get("services", [])}
    given = [key for key in checks if key in entry]
    return bool(given) and all(any(fnmatch.fnmatchcase(v, str(entry[key])) for v in checks[key]) for key in given)


def write_baseline(findings: list[Finding], path: Path) -> None:
    entries = sorted({(f.fingerprint, f.rule.id, f.message) for f in findings if f.suppression is None})
    document = {"version": BASELINE_VERSION,
                "findings": [{"fingerprint": fp, "rule": rule, "message": msg} for fp, rule, msg in entries]}
    path.write_text(json.dumps(document, indent=1) + "\n", encoding="utf-8")


def read_baseline(path: Path) -> set[str]:
    try:
        document = json.loads(path.read_text(encoding="utf-8"))
        return {entry["fingerprint"] for entry in document["findings"]}
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise ValueError(f"{path}: not an archlog baseline ({exc})") from None
