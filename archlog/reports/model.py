"""What every report format is made from: findings, diagnostics, the rules that ran, the root."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from archlog.diagnostics import SEVERITIES, Diagnostic
from archlog.rules.engine import Finding
from archlog.rules.ruleset import Rule


@dataclass
class Report:
    findings: list[Finding]
    diagnostics: list[Diagnostic]
    rules: list[Rule]
    root: Path

    def counts(self) -> dict[str, int]:
        """Findings per severity, not counting suppressed ones."""
        return {s: sum(f.severity == s and f.suppression is None for f in self.findings) for s in SEVERITIES}

    @property
    def suppressed(self) -> int:
        return sum(f.suppression is not None for f in self.findings)

    def source_line(self, file: str, line: int) -> str | None:
        path = Path(file) if Path(file).is_absolute() else self.root / file
        try:
            with path.open(encoding="utf-8", errors="replace") as fh:
                for number, text in enumerate(fh, 1):
                    if number == line:
                        return text.rstrip("\n")
        except OSError:
            return None
        return None
