"""Terminal output: findings grouped by file, the source line with a marker, both sides named."""

from __future__ import annotations

import os
from itertools import groupby
from typing import TextIO

from rich.console import Console
from rich.markup import escape

from archlog.reports.report import Report
from archlog.reports.rule_help import hint

STYLE = {"error": "bold red", "warning": "yellow", "note": "cyan"}
NOTES_SHOWN = 3  # notes of one code printed before the rest are counted


def print_text(report: Report, console: Console, quiet: bool = False) -> None:
    """Findings grouped by file with their source lines; `quiet`: one line each and the summary."""
    active = [f for f in report.findings if f.suppression is None]
    for file, findings in groupby(active, key=lambda f: f.location.file):
        console.print(f"[bold underline]{escape(file)}[/]")
        for f in findings:
            loc = f.location
            console.print(f"  {loc.line}:{loc.column} [{STYLE[f.severity]}]{f.severity}[/] "
                          f"{escape(f.message)} [dim]{f.rule.id} {f.rule.name}[/]")
            if quiet:
                continue
            _source(report, console, loc.file, loc.line, loc.column)
            for rel in f.related:
                console.print(f"    [dim]{escape(report.label(rel))}:[/] {escape(rel.file)}:{rel.line}")
                _source(report, console, rel.file, rel.line, rel.column)
            if hint(f.rule):
                console.print(f"    [dim]fix:[/] {escape(hint(f.rule, f.values))}", highlight=False)
        if not quiet:
            console.print()
    if report.diagnostics and not quiet:
        console.print("[bold]diagnostics[/] (problems reading the input)")
        shown: dict[tuple[str, str], int] = {}
        for d in report.diagnostics:
            if d.severity == "note":  # repeated notes of one cause in one file: the first few, then a count
                shown[d.code, d.file] = shown.get((d.code, d.file), 0) + 1
                if shown[d.code, d.file] > NOTES_SHOWN:
                    continue
            console.print(f"  {escape(d.file)}:{d.line}: [{STYLE[d.severity]}]{d.severity}[/] "
                          f"{escape(d.message)} [dim]{d.code}[/]")
        for (code, file), n in shown.items():
            if n > NOTES_SHOWN:
                console.print(f"  ... and {n - NOTES_SHOWN} more {code} notes like these in {escape(file)} "
                              "(--format json lists each)", highlight=False)
        console.print()
    console.print(escape(summary_line(report, recovery=False)), highlight=False)
    print_coverage(report, console)


def _plural(n: int, word: str) -> str:
    return f"{n} {word}{'s' if n != 1 else ''}"


def summary_line(report: Report, recovery: bool = True) -> str:
    """One line: findings per severity, suppressed and hidden ones, diagnostics, recovery."""
    counts = report.counts()
    parts = [f"{_plural(sum(counts.values()), 'finding')} ({', '.join(_plural(n, s) for s, n in counts.items())})"]
    if report.suppressed:
        parts.append(f"{report.suppressed} suppressed")
    parts += [f"{n} {why} not shown" for why, n in report.hidden.items()]
    parts.append(_plural(len(report.diagnostics), "diagnostic"))
    if report.coverage and recovery:
        n = report.coverage_counts()
        parts.append(f"{n['recovered']} of {len(report.coverage)} nodes fully recovered")
    return "; ".join(parts)


def print_coverage(report: Report, console: Console) -> None:
    """The recovery summary: nodes fully recovered, partial (each reason with file:line), opaque."""
    if not report.coverage and not report.holes:
        return
    n = report.coverage_counts()
    unread = f"; {len(report.holes)} part{'s' if len(report.holes) != 1 else ''} of the configuration not read" \
        if report.holes else ""
    console.print(f"[bold]recovery[/]: {n['recovered']} of {len(report.coverage)} node"
                  f"{'s' if len(report.coverage) != 1 else ''} fully recovered, {n['partial']} partial, "
                  f"{n['opaque']} opaque (no model or source){unread}")
    for why, file, line in report.holes:
        console.print(f"  not read: {escape(why)} ({escape(file)}:{line})", highlight=False)
    for c in report.coverage:
        if c.status == "recovered":
            continue
        for why, file, line in c.reasons:
            where = f" ({escape(file)}:{line})" if file else ""
            console.print(f"  {c.status} {escape(c.node)}: {escape(why)}{where}", highlight=False)


def _source(report: Report, console: Console, file: str, line: int, column: int) -> None:
    text = report.source_line(file, line)
    if text is None:
        return
    console.print(f"    [dim]{line:>4} |[/] {escape(text)}", highlight=False)
    if column > 0:
        console.print(f"    [dim]     |[/] {' ' * (column - 1)}[bold]^[/]", highlight=False)


def print_concise(report: Report, out: TextIO) -> None:
    """One `path:line:col: ID message` line per finding, then per diagnostic that is not a note
    (code for id), with paths relative to the current folder so that editors and terminals open
    them; then the one-line summary."""
    def where(file: str, line: int, column: int) -> str:
        path = report.root / file if file else None
        shown = os.path.relpath(path) if path is not None else "."
        return f"{shown}:{max(line, 1)}:{max(column, 1)}"

    for f in report.findings:
        if f.suppression is None:
            loc = f.location
            out.write(f"{where(loc.file, loc.line, loc.column)}: {f.rule.id} {f.message}\n")
    for d in report.diagnostics:
        if d.severity != "note":  # notes are counted in the summary; --format text lists them
            out.write(f"{where(d.file, d.line, d.column)}: {d.code} {d.message}\n")
    out.write(summary_line(report) + "\n")
