"""Two CI formats: GitHub Actions workflow commands (`--format github`: one annotation per finding
and per diagnostic that is not a note) and JUnit XML (`--format junit`: one failing test case per
finding, so any CI that shows test results shows them)."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from archlog.reports.report import Report
from archlog.reports.text import summary_line

COMMANDS = {"error": "error", "warning": "warning", "note": "notice"}


def _data(text: str) -> str:
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _property(text: str) -> str:
    return _data(text).replace(":", "%3A").replace(",", "%2C")


def _command(severity: str, file: str, line: int, column: int, title: str, message: str) -> str:
    where = f"file={_property(file)},line={max(line, 1)}" + (f",col={column}" if column > 0 else "") if file else ""
    properties = ",".join(p for p in (where, f"title={_property(title)}") if p)
    return f"::{COMMANDS[severity]} {properties}::{_data(message)}\n"


def to_github(report: Report) -> str:
    lines = [_command(f.severity, f.location.file, f.location.line, f.location.column, f"{f.rule.id} {f.rule.name}",
                      f.message) for f in report.findings if f.suppression is None]
    lines += [_command(d.severity, d.file, d.line, d.column, d.code, d.message) for d in report.diagnostics
              if d.severity != "note"]
    return "".join(lines) + f"archlog: {summary_line(report)}\n"


def to_junit(report: Report) -> str:
    active = [f for f in report.findings if f.suppression is None]
    suite = ET.Element("testsuite", name="archlog", tests=str(max(len(active), 1)), failures=str(len(active)),
                       errors="0", skipped=str(report.suppressed))
    if not active:
        ET.SubElement(suite, "testcase", classname="archlog", name="check")
    for f in active:
        case = ET.SubElement(suite, "testcase", classname=f"{f.rule.id} {f.rule.name}",
                             name=f"{f.location.file}:{f.location.line}", file=f.location.file, line=str(f.location.line))
        failure = ET.SubElement(case, "failure", message=f.message, type=f.severity)
        failure.text = "\n".join([f"{f.location.file}:{f.location.line}: {f.message}",
                                  *(f"related: {r.file}:{r.line}" for r in f.related)])
    ET.SubElement(suite, "system-out").text = summary_line(report)
    root = ET.Element("testsuites", name="archlog", tests=suite.get("tests", "0"), failures=str(len(active)))
    root.append(suite)
    ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"
