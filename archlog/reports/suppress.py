"""Suppressions and baselines.

Inline: `<!-- archlog: ignore[AL401] reason -->` (launch XML), `// archlog: ignore[AL102] reason`
(C++) or `# archlog: ignore[AL102] reason` (Python) on the finding's line or the line above.
A comment on (or above) a node's `<node>`/`Node(...)` applies to every finding about that node.
Configured: `[[suppress]]` tables in archlog.toml (docs/suppressions.md). A suppressed finding
stays in the report, marked; a suppression that matches nothing is reported. A baseline file holds
the fingerprints of accepted findings; its entries that match nothing are reported too.
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


def apply_suppressions(findings: list[Finding], files: set[str], root: Path, configured: list[dict],
                       config_file: str = "", elements: dict[str, tuple[str, int]] | None = None) -> list[Diagnostic]:
    """Mark suppressed findings; returns a diagnostic for each inline suppression and each
    configured entry left unused. An inline suppression on (or above) the launch element of a
    node instance (`elements`: node -> its element's file and line) applies to the findings about
    that instance, wherever they are located."""
    inline = inline_suppressions(files, root)
    texts: dict[Path, list[str]] = {}
    used: set[tuple[str, int]] = set()
    entries_used: set[int] = set()
    for finding in findings:
        loc = finding.location
        lines = [(loc.file, loc.line), (loc.file, loc.line - 1)]
        nodes = finding.subjects.get("nodes", [])
        if elements and nodes and nodes[0] in elements:
            file, line = elements[nodes[0]]
            start = _element_start(file, line, root, texts)
            lines += [(file, start), (file, start - 1)]
        for key in lines:
            mark = inline.get(key)
            if mark and (finding.rule.id in mark.rules or finding.rule.name in mark.rules):
                finding.suppression = ("inSource", mark.reason or "suppressed in source")
                used.add((mark.file, mark.line))
                break
        if finding.suppression is None:
            index = next((i for i, e in enumerate(configured) if _matches(e, finding)), None)
            if index is not None:
                entries_used.add(index)
                finding.suppression = ("external", str(configured[index].get("reason",
                                                                             "suppressed in the configuration")))
    return [Diagnostic(mark.file, mark.line, "unused-suppression",
                       f"suppression of {', '.join(mark.rules)} matches no finding here; remove it", "warning")
            for key, mark in sorted(inline.items()) if key not in used] + \
        [Diagnostic(config_file, int(entry.get("line", 0)), "unused-suppression",
                    "[[suppress]] " + ", ".join(f"{k} = {entry[k]!r}" for k in ("rule", "node", "topic", "service")
                                                if k in entry) + " matches no finding; remove it", "warning")
         for i, entry in enumerate(configured) if i not in entries_used]


def _element_start(file: str, line: int, root: Path, texts: dict[Path, list[str]]) -> int:
    """The line where the launch element ending its start tag on `line` begins (`<node`, `Node(`);
    `texts` holds the lines of each file read so far (one launch file may start thousands of nodes)."""
    path = Path(file) if Path(file).is_absolute() else root / file
    if path not in texts:
        try:
            texts[path] = sandbox.read_text(path, "source").splitlines()
        except sandbox.Refused:
            texts[path] = []
    lines = texts[path]
    if not lines:
        return line
    for number in range(min(line, len(lines)), max(line - 20, 0), -1):
        if re.search(r"<node\b|Node\s*\(", lines[number - 1]):
            return number
    return line


def _matches(entry: dict, finding: Finding) -> bool:
    checks = {"rule": [finding.rule.id, finding.rule.name], "node": finding.subjects.get("nodes", []),
              "topic": finding.subjects.get("topics", []), "service": finding.subjects.get("services", [])}
    given = [key for key in checks if key in entry]
    return bool(given) and all(any(fnmatch.fnmatchcase(v, str(entry[key])) for v in checks[key]) for key in given)


def write_baseline(findings: list[Finding], path: Path) -> int:
    """Record the unsuppressed findings; returns how many entries were written."""
    entries = sorted({(f.fingerprint, f.rule.id, f.message) for f in findings if f.suppression is None})
    document = {"version": BASELINE_VERSION,
                "findings": [{"fingerprint": fp, "rule": rule, "message": msg} for fp, rule, msg in entries]}
    path.write_text(json.dumps(document, indent=1) + "\n", encoding="utf-8")
    return len(entries)


def stale_baseline(path: Path, known: set[str], found: set[str]) -> list[Diagnostic]:
    """A diagnostic at each baseline entry that no finding of this run matches."""
    lines = path.read_text(encoding="utf-8").splitlines()
    return [Diagnostic(str(path), next((n for n, text in enumerate(lines, 1) if fingerprint in text), 0),
                       "stale-baseline", f"baseline entry {fingerprint} matches no finding; remove it "
                       "(or write the baseline again)", "warning")
            for fingerprint in sorted(known - found)]


def read_baseline(path: Path) -> set[str]:
    try:
        document = json.loads(path.read_text(encoding="utf-8"))
        return {entry["fingerprint"] for entry in document["findings"]}
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise ValueError(f"{path}: not an archlog baseline ({exc})") from None
