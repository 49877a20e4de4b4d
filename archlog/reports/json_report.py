"""The JSON report; its schema is findings.schema.json next to this file (docs/output-json.md)."""

from __future__ import annotations

import json

from archlog import __version__
from archlog.reports.report import Report
from archlog.reports.rule_help import hint, url
from archlog.rules.engine import Location

FORMAT_VERSION = 1


def _location(loc: Location, role: str, label: str = "") -> dict:
    return {"file": loc.file, "line": loc.line, "column": loc.column, "role": role, **({"label": label} if label else {})}


def to_json(report: Report) -> str:
    findings = [
        {
            "rule": f.rule.id,
            "name": f.rule.name,
            "severity": f.severity,
            "message": f.message,
            "help": hint(f.rule, f.values),
            "url": url(f.rule),
            "locations": [_location(f.location, "primary")] + [_location(r, "related", report.label(r, ""))
                                                              for r in f.related],
            "subjects": f.subjects,
            "fingerprint": f.fingerprint,
            **({"suppressed": {"kind": f.suppression[0], "justification": f.suppression[1]}}
               if f.suppression else {}),
        }
        for f in report.findings
    ]
    diagnostics = [
        {"code": d.code, "severity": d.severity, "message": d.message, "file": d.file, "line": d.line,
         "column": d.column}
        for d in report.diagnostics
    ]
    document = {
        "format": FORMAT_VERSION,
        "tool": {"name": "archlog", "version": __version__},
        "root": str(report.root.resolve()),
        "findings": findings,
        "diagnostics": diagnostics,
        "summary": report.counts(),
        "hidden": report.hidden,
        "coverage": {
            **report.coverage_counts(),
            "nodes": [
                {"node": c.node, "status": c.status, "origin": c.origin,
                 "reasons": [{"message": why, "file": file, "line": line} for why, file, line in c.reasons]}
                for c in report.coverage
            ],
            "holes": [{"message": why, "file": file, "line": line} for why, file, line in report.holes],
        },
    }
    return json.dumps(document, indent=2) + "\n"
