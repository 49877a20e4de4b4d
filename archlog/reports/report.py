"""What every report format is made from: findings, diagnostics, the rules that ran, the root."""

from __future__ import annotations

import io
import re
from dataclasses import dataclass, field
from pathlib import Path

from archlog import sandbox
from archlog.diagnostics import SEVERITIES, Diagnostic
from archlog.facts.compose import NAMED_PORTS
from archlog.rules.engine import Finding, Location
from archlog.rules.ruleset import Rule
from archlog.values import Unknown

STATUSES = ("recovered", "partial", "opaque")
_WHERE = re.compile(r"^(?P<file>[^:\n]+?)(?::(?P<line>\d+))?: (?P<why>.*)$", re.S)


@dataclass
class NodeCoverage:
    """How completely a node instance was recovered: `recovered` (its model or source read whole),
    `partial` (read, but something is missing: each reason with its file and line) or `opaque`
    (neither a model nor a source)."""

    node: str
    status: str
    origin: str  # cpp, python, model, or empty when opaque
    reasons: list[tuple[str, str, int]] = field(default_factory=list)  # (why, file, line)


def coverage(store) -> list[NodeCoverage]:
    """Each node instance of the system, by name, with what keeps its recovery from being complete."""
    origins = {str(name): str(origin) for name, origin in store.rows("node_source")}
    incomplete: dict[str, list[str]] = {}
    for name, reason in store.rows("node_incomplete"):
        incomplete.setdefault(str(name), []).append(str(reason))
    unnamed: dict[str, list[tuple[str, str, int]]] = {}
    for rel in NAMED_PORTS:
        for port, node, name, *_rest in store.rows(rel):
            if isinstance(name, Unknown):
                file, line, _column = store.location(str(port)) or (name.file, name.line, 0)
                unnamed.setdefault(str(node), []).append(
                    (f"{rel.replace('_', ' ')} name unknown: {name.expr}", file, line))
    result = []
    for name, pkg, exe, elem in sorted(store.rows("node"), key=lambda row: str(row[0])):
        node = str(name)
        file, line, _column = store.location(str(elem)) or ("", 0, 0)
        if node not in origins:
            result.append(NodeCoverage(node, "opaque", "", [(f"no model or source for {pkg}/{exe}", file, line)]))
            continue
        reasons = []
        for reason in incomplete.get(node, []):
            where = _WHERE.match(reason)
            if where and ("/" in where["file"] or "." in where["file"]):
                reasons.append((where["why"], where["file"], int(where["line"] or 0)))
            else:
                reasons.append((reason, file, line))
        reasons += sorted(set(unnamed.get(node, [])), key=lambda r: (r[1], r[2], r[0]))
        result.append(NodeCoverage(node, "partial" if reasons else "recovered", origins[node], reasons))
    return result


def holes(store) -> list[tuple[str, str, int]]:
    """The parts of the configuration not read (launch_hole, plugin_hole), as (why, file, line)."""
    found = []
    rows = [*store.rows("launch_hole"), *((hole, why) for hole, _node, why in store.rows("plugin_hole"))]
    for hole, why in rows:
        file, line, _column = store.location(str(hole)) or ("", 0, 0)
        found.append((str(why), file, line))
    return sorted(found, key=lambda h: (h[1], h[2], h[0]))


@dataclass
class Report:
    findings: list[Finding]
    diagnostics: list[Diagnostic]
    rules: list[Rule]
    root: Path
    origins: dict[str, list[tuple[Location, str]]] = field(default_factory=dict)
    coverage: list[NodeCoverage] = field(default_factory=list)
    labels: dict[tuple[str, int, int], str] = field(default_factory=dict)  # what a related location is
    hidden: dict[str, int] = field(default_factory=dict)  # findings left out, by why (baseline, --new-only)

    def label(self, loc: Location, default: str = "the other side") -> str:
        """What a related location of a finding is: the model a finding was moved from, else `default`."""
        return self.labels.get((loc.file, loc.line, loc.column), default)
    holes: list[tuple[str, str, int]] = field(default_factory=list)  # (why, file, line): launch parts not read

    @staticmethod
    def node_origins(store) -> dict[str, list[tuple[Location, str]]]:
        """For each node instance: its launch element, then the includes it was loaded through."""
        includes: dict[str, list[tuple[int, str]]] = {}
        for elem, include, depth in store.rows("included_through"):
            includes.setdefault(elem, []).append((depth, include))
        origins = {}
        for name, _pkg, _exe, elem in store.rows("node"):
            chain = [(Location(*store.location(elem)), f"node {name} is declared here")]
            for depth, include in sorted(includes.get(elem, []), reverse=True):
                chain.append((Location(*store.location(include)), f"included from here (level {depth})"))
            origins[str(name)] = chain
        return origins

    def counts(self) -> dict[str, int]:
        """Findings per severity, not counting suppressed ones."""
        return {s: sum(f.severity == s and f.suppression is None for f in self.findings) for s in SEVERITIES}

    def coverage_counts(self) -> dict[str, int]:
        """Node instances per recovery status."""
        return {s: sum(c.status == s for c in self.coverage) for s in STATUSES}

    @property
    def incomplete(self) -> bool:
        return bool(self.holes) or any(c.status != "recovered" for c in self.coverage)

    @property
    def suppressed(self) -> int:
        return sum(f.suppression is not None for f in self.findings)

    def source_line(self, file: str, line: int) -> str | None:
        path = Path(file) if Path(file).is_absolute() else self.root / file
        try:
            lines = io.StringIO(sandbox.read_text(path, "source"), newline=None).read().split("\n")
        except sandbox.Refused:
            return None
        return lines[line - 1] if 0 < line <= len(lines) else None
