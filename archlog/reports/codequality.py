"""GitLab Code Quality report (the `codequality` artifact of a merge request)."""

from __future__ import annotations

import json

from archlog.reports.report import Report

SEVERITY = {"error": "major", "warning": "minor", "note": "info"}


def to_codequality(report: Report) -> str:
    issues = [
        {
            "description": f"{f.rule.id} {f.message}",
            "check_name": f.rule.name,
            "fingerprint": f.fingerprint,
            "severity": SEVERITY[f.severity],
            "location": {"path": f.location.file, "lines": {"begin": max(f.location.line, 1)}},
        }
        for f in report.findings
        if f.suppression is None
    ]
    return json.dumps(issues, indent=2) + "\n"
