"""A stable text rendering of what an extractor recovered, for CodeQL-style .expected files."""

from __future__ import annotations

import json

from archlog.diagnostics import Diagnostic
from archlog.extract.summary import NodeSummary, Publish, Site
from archlog.values import Alternatives, Concat, Namespace, ParamList, ParamRef, Unknown, Value


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
    if isinstance(value, Namespace):
        return {"namespace_of": plain(value.handle), **({"cut": value.cut} if value.cut else {})}
    if isinstance(value, ParamList):
        return {"each_of_param": value.name, **({"field": value.field} if value.field else {}),
                **({"defaults": list(value.defaults)} if value.defaults is not None else {})}
    return value


def describe(summary: NodeSummary, diagnostics: list[Diagnostic]) -> str:
    lines = [f"node {json.dumps(plain(summary.default_name))} namespace {json.dumps(plain(summary.namespace))}"
             f" anonymous {summary.anonymous}"]
    lines += [f"incomplete {summary.incomplete}"] if summary.incomplete else []
    lines += [f"built-in ports {' '.join(summary.infrastructure) or '-'} without {' '.join(summary.without) or '-'}"] \
        if summary.infrastructure or summary.without else []
    for p in summary.ports:
        extra = f" default {json.dumps(plain(p.default))}" if p.default is not None else ""
        extra += "".join(f" {k}={v}" for k, v in p.qos)
        handle = f" handle {json.dumps(plain(p.handle_ns))}" if p.handle_ns else ""
        extra += f" if {json.dumps(plain(p.condition[0]))}={p.condition[1]}" if p.condition else ""
        extra += "".join(f" and {json.dumps(plain(value))}={wanted}" for value, wanted in p.also)
        elsewhere = summary.origin == "python" and summary.name_file and p.file != summary.name_file
        site = f"{p.file}:{p.line}" if elsewhere else p.line  # a port of a module the script calls
        lines.append(f"{site}: {p.kind} {json.dumps(plain(p.name))} {json.dumps(plain(p.type))}{handle}{extra}")
    lines += [f"{n.line}: load {json.dumps(plain(n.plugin))} as {json.dumps(plain(n.name))}"
              + "".join(f" {json.dumps(plain(k))}:={json.dumps(plain(v))}" for k, v in n.remaps) for n in summary.loads]
    lines += [f"{file}:{line}: creates pluginlib classes (not read)" for file, line in summary.plugin_loads]
    for other in summary.others:  # further nodes of the same process
        lines += ["also " + line for line in describe(other, []).splitlines()]
    lines += [f"diagnostic {d.line}: {d.severity} {d.code}" for d in diagnostics]
    lines += [describe_publish(p) for p in summary.publishes]
    lines += [f"write {w.line} {w.var}={w.value}" + (f" by {_site(w.source, w.file)}" if w.source else "")
              for w in summary.writes]
    return "\n".join(lines) + "\n"


def describe_publish(p: Publish) -> str:
    """`publish LINE -> PUBLISHER trigger KIND [SOURCE] [period SECONDS] [guards VAR=VALUE@LINE...]`;
    sites are lines of the same file (file:line otherwise), ? when not known."""
    text = f"publish {p.line} -> {_site(p.publisher, p.file) if p.publisher else '?'} trigger {p.trigger}"
    text += f" {_site(p.source, p.file)}" if p.source else ""
    text += f" period {json.dumps(plain(p.period))}" if p.period is not None else ""
    guards = " ".join(f"{g.var}={g.value}@{g.line}" if g.file == p.file else f"{g.var}={g.value}@{g.file}:{g.line}"
                      for g in p.guards)
    return text + (f" guards {guards}" if guards else "")


def _site(site: Site, file: str) -> str:
    return str(site.line) if site.file == file else f"{site.file}:{site.line}"
