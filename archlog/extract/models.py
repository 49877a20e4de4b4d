"""Hand-written YAML node models for nodes without source, and external producers/consumers.

A model file holds one model or a list under `models:`. Each model names `package` and
`executable` (or `instance`, the resolved name of an external node that is always part of the
configuration) and lists its ports. A name may be a string or `{param: NAME, default: VALUE}`.
"""

from __future__ import annotations

from pathlib import Path

import yaml

from archlog.diagnostics import DiagnosticSink
from archlog.extract.summary import NodeSummary, Port
from archlog.values import ParamRef, Value

SECTIONS = {
    "publishers": "publisher", "subscribers": "subscriber",
    "services": "service_server", "service_clients": "service_client",
    "actions": "action_server", "action_clients": "action_client",
    "params": "param_read",
}
BUILTIN_DIR = Path(__file__).resolve().parent.parent / "models"


class _LineLoader(yaml.SafeLoader):
    """A YAML loader that records each mapping's line as key '__line__'."""

    def construct_mapping(self, node: yaml.MappingNode, deep: bool = False) -> dict:
        mapping = super().construct_mapping(node, deep=deep)
        mapping["__line__"] = node.start_mark.line + 1
        return mapping


def load_models(path: Path, shown: str, diagnostics: DiagnosticSink) -> list[tuple[NodeSummary, str | None]]:
    """(summary, external instance name or None) for every valid model in the file."""
    try:
        data = yaml.load(path.read_text(encoding="utf-8"), Loader=_LineLoader)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        diagnostics.add(shown, mark.line + 1 if mark else 1, "model-yaml", f"model file does not parse: {exc}", "error")
        return []
    except OSError as exc:
        diagnostics.add(shown, 1, "model-read", f"cannot read model file: {exc.strerror}", "error")
        return []
    items = data.get("models", []) if isinstance(data, dict) and "models" in data else [data]
    result = []
    for item in items:
        line = item.get("__line__", 1) if isinstance(item, dict) else 1
        if not isinstance(item, dict) or not (item.get("instance") or (item.get("package") and item.get("executable"))):
            diagnostics.add(shown, line, "model-schema", "a model needs `package` and `executable`, or `instance`", "error")
            continue
        instance = item.get("instance")
        summary = NodeSummary(str(item.get("package", "external")), str(item.get("executable", instance)), "model",
                              default_name=str(item.get("name", instance or item["executable"])))
        for section, kind in SECTIONS.items():
            for port in item.get(section) or []:
                _port(summary, kind, port, shown, diagnostics)
        result.append((summary, instance))
    return result


def _port(summary: NodeSummary, kind: str, port: object, shown: str, diagnostics: DiagnosticSink) -> None:
    if not isinstance(port, dict) or "name" not in port or (kind != "param_read" and "type" not in port):
        line = port.get("__line__", 1) if isinstance(port, dict) else 1
        diagnostics.add(shown, line, "model-schema", f"each entry of a {kind} list needs `name` and `type`", "error")
        return
    default = port.get("default")
    summary.ports.append(Port(kind, _name(port["name"], shown, port["__line__"]), str(port.get("type", "")),
                              shown, port["__line__"], 0, "", None if default is None else str(default)))


def _name(raw: object, shown: str, line: int) -> Value:
    if isinstance(raw, dict) and "param" in raw:
        return ParamRef(str(raw["param"]), str(raw.get("default", "")), "", shown, line)
    return str(raw)
