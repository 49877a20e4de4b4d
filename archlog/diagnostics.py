"""Diagnostics: problems with the input (not findings about the system), always with file:line."""

from __future__ import annotations

from dataclasses import dataclass, field

SEVERITIES = ("error", "warning", "note")


@dataclass(frozen=True, order=True)
class Diagnostic:
    """A problem archlog met while reading the input, e.g. a launch file that does not parse."""

    file: str
    line: int
    code: str
    message: str
    severity: str = "warning"
    column: int = 0

    def __str__(self) -> str:
        return f"{self.file}:{self.line}: {self.severity}: {self.message} [{self.code}]"


@dataclass
class DiagnosticSink:
    """Collects diagnostics from every stage; order of arrival is kept and duplicates dropped."""

    items: list[Diagnostic] = field(default_factory=list)

    def add(self, file: str, line: int, code: str, message: str, severity: str = "warning", column: int = 0) -> None:
        diag = Diagnostic(str(file), line, code, message, severity, column)
        if diag not in self.items:
            self.items.append(diag)
