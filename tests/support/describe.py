"""A stable text rendering of what an extractor recovered, for CodeQL-style .expected files."""

from __future__ import annotations

import json

from archlog.diagnostics import Diagnostic
from archlog.extract.summary import NodeSummary
from archlog.values import Alternatives, Concat, ParamRef, Unknown, Value


def plain(value: Value | None) -> object:
    if isinstance(value, Unknown):
        return {"unknown": value.expr, "line": value.line}
    if isinstance(value, ParamRef):
        handle = {"handle": plain(value.handle_ns)} if value.handle_ns else {}
        return {"param": value.name, **handle, "default": plain(value.default)}
    if isinstance(value, Concat):
        return {"concat": [plain(p) for p in value.parts]}
    if isinstance(value, Alternatives):
        return {"every" if value.every else "one_of": [plain(p) for p in value.options]}
    return value


def describe(summary: NodeSummary, diagnostics: list[Diagnostic]) -> str:
    lines = [f"node {json.dumps(plain(summary.default_name))} namespace {json.dumps(plain(summary.namespace))}"
             f" anonymous {summary.anonymous}"]
    lines += [f"incomplete {summary.incomplete}"] if summary.incomplete else []
    for p in summary.ports:
        extra = f" default {json.dumps(plain(p.default))}" if p.default is not None else ""
        extra += "".join(f" {k}={v}" for k, v in p.qos)
        handle = f" handle {json.dumps(plain(p.handle_ns))}" if p.handle_ns else ""
        lines.append(f"{p.line}: {p.kind} {json.dumps(plain(p.name))} {json.dumps(plain(p.type))}{handle}{extra}")
    lines += [f"diagnostic {d.line}: {d.severity} {d.code}" for d in diagnostics]
    return "\n".join(lines) + "\n"
