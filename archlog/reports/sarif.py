"""SARIF 2.1.0: rules with full metadata, results with related locations, diagnostics as notifications."""

from __future__ import annotations

import json
from pathlib import Path

from archlog import __version__
from archlog.reports.report import Report
from archlog.reports.rule_help import INFO_URI, help_text, url
from archlog.rules.engine import Finding, Location

LEVELS = {"error": "error", "warning": "warning", "note": "note"}
SECURITY = {"error": "error", "warning": "warning", "note": "recommendation"}


def _physical(loc: Location, root: Path) -> dict:
    path = Path(loc.file)
    artifact = {"uri": path.as_uri()} if path.is_absolute() else {"uri": path.as_posix(), "uriBaseId": "SRCROOT"}
    physical: dict = {"artifactLocation": artifact}
    if loc.line > 0:
        region = {"startLine": loc.line}
        if loc.column > 0:
            region["startColumn"] = loc.column
        physical["region"] = region
    return physical


def _escape(text: str) -> str:
    """Message text with literal brackets escaped, so that only archlog's links are links."""
    return text.replace("[", "\\[").replace("]", "\\]")


def _related(f: Finding, report: Report) -> list[tuple[Location, str]]:
    """The finding's other sides, then the launch elements and includes of the nodes it names."""
    related = [(r, report.label(r)) for r in f.related]
    for node in f.subjects.get("nodes", []):
        related += report.origins.get(node, [])
    return [(loc, text) for loc, text in related if loc.file]


def _linked(message: str, related: list[tuple[Location, str]]) -> str:
    """The message with a link to each related location (GitHub shows only linked ones)."""
    if not related:
        return _escape(message)
    links = ", ".join(f"[{_escape(text)}]({i})" for i, (_loc, text) in enumerate(related, 1))
    return f"{_escape(message)} (see {links})"


def to_sarif(report: Report) -> str:
    rules = report.rules
    index = {r.id: i for i, r in enumerate(rules)}
    driver_rules = [
        {
            "id": r.id,
            "name": r.name,
            "shortDescription": {"text": r.summary},
            "fullDescription": {"text": r.description or r.summary},
            "help": {"text": help_text(r) or r.summary, "markdown": help_text(r) or r.summary},
            **({"helpUri": url(r)} if url(r) else {}),
            "defaultConfiguration": {"level": LEVELS[r.severity]},
            "properties": {"tags": r.tags, "precision": r.precision, "problem.severity": SECURITY[r.severity]},
        }
        for r in rules
    ]
    results = []
    for f in report.findings:
        related = _related(f, report)
        result = {
            "ruleId": f.rule.id,
            "ruleIndex": index[f.rule.id],
            "level": LEVELS[f.severity],
            "message": {"text": _linked(f.message, related)},
            "locations": [{"physicalLocation": _physical(f.location, report.root)}],
            "partialFingerprints": {"archlogFingerprint/v1": f.fingerprint},
        }
        if f.suppression:
            result["suppressions"] = [{"kind": f.suppression[0], "justification": f.suppression[1]}]
        if related:
            result["relatedLocations"] = [
                {"id": i, "physicalLocation": _physical(loc, report.root), "message": {"text": text}}
                for i, (loc, text) in enumerate(related, 1)
            ]
        results.append(result)
    notifications = [
        {
            "level": LEVELS[d.severity],
            "message": {"text": d.message},
            "descriptor": {"id": d.code},
            "locations": [{"physicalLocation": _physical(Location(d.file, d.line, d.column), report.root)}],
        }
        for d in report.diagnostics
    ]
    for c in report.coverage:  # nodes whose recovery is not complete, one notification per reason
        for why, file, line in c.reasons if c.status != "recovered" else []:
            notification: dict = {
                "level": "note",
                "message": {"text": f"node {c.node} is {c.status}ly recovered: {why}" if c.status == "partial"
                            else f"node {c.node} is opaque: {why}"},
                "descriptor": {"id": f"recovery-{c.status}"},
                "properties": {"node": c.node, "status": c.status},
            }
            if file:
                notification["locations"] = [{"physicalLocation": _physical(Location(file, line, 0), report.root)}]
            notifications.append(notification)
    notifications += [{"level": "note", "message": {"text": f"part of the configuration not read: {why}"},
                       "descriptor": {"id": "recovery-hole"},
                       "locations": [{"physicalLocation": _physical(Location(file, line, 0), report.root)}]}
                      for why, file, line in report.holes]
    run = {
        "tool": {"driver": {"name": "archlog", "version": __version__, "semanticVersion": __version__,
                            "informationUri": INFO_URI, "rules": driver_rules}},
        "originalUriBaseIds": {"SRCROOT": {"uri": report.root.resolve().as_uri() + "/"}},
        "invocations": [{"executionSuccessful": True, "toolExecutionNotifications": notifications,
                         "properties": {"coverage": report.coverage_counts(), "hidden": report.hidden}}],
        "results": results,
        "columnKind": "unicodeCodePoints",
    }
    document = {
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [run],
    }
    return json.dumps(document, indent=2) + "\n"
