"""What every report format is made from: findings, diagnostics, the rules that ran, the root."""

from __future__ import annotations

import io
from dataclasses import dataclass, field
from pathlib import Path

from archlog import sandbox
from archlog.diagnostics import SEVERITIES, Diagnostic
from archlog.rules.engine import Finding, Location
from archlog.rules.ruleset import Rule


@dataclass
class Report:
    findings: list[Finding]
    diagnostics: list[Diagnostic]
    rules: list[Rule]
    root: Path
    origins: dict[str, list[tuple[Location, str]]] = field(default_factory=dict)

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
