"""Ports listed in a YAML file that a node's parameter names: yocs_cmd_vel_mux reads the file its
`~yaml_cfg_file` names (with yaml-cpp) and subscribes to every `subscribers[].topic` in it. A
model writes such a name `{file: PARAM, key: KEY, field: FIELD}` (a `ParamList` with an `entry`);
each instance gets one port per element of the list KEY of its file (or one port when KEY is a
string, or `default` when the file lacks KEY), placed at that entry's line of the file, so a
finding about the port points into it. The file is read through the sandbox, within the budget."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import yaml

from archlog import budget, names, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.bounded_yaml import BoundedLoader
from archlog.extract.launch.model import LaunchConfig, LaunchNode
from archlog.extract.summary import Port
from archlog.extract.workspace.index import Workspace
from archlog.values import ParamList, Unknown


def listed(port: Port) -> bool:
    """A port whose names are listed in a file a parameter names."""
    return isinstance(port.name, ParamList) and bool(port.name.entry)


def file_ports(node: LaunchNode, ports: list[Port], config: LaunchConfig, workspace: Workspace,
               diagnostics: DiagnosticSink) -> list[Port]:
    """The ports, with each one listed in a parameter's file replaced by the ports the file lists."""
    return [expanded for port in ports
            for expanded in (_listed_ports(port, node, config, workspace, diagnostics) if listed(port) else [port])]


def _listed_ports(port: Port, node: LaunchNode, config: LaunchConfig, workspace: Workspace,
                  diagnostics: DiagnosticSink) -> list[Port]:
    spec = port.name
    assert isinstance(spec, ParamList)
    param = names.resolve(spec.name, node.namespace, node.name)
    value, elem = config.params.get(param, (None, None))
    if not isinstance(value, str) or not value:
        why = "not set by the configuration" if value is None else f"not a file name: {value}"
        return [replace(port, name=Unknown(f"{spec.entry} of the file {param} names ({why})", spec.file, spec.line))]
    at = (elem.file, elem.line) if elem is not None else (node.elem.file, node.elem.line)
    if not Path(value).is_absolute():
        diagnostics.add(at[0], at[1], "ports-file", f"{param} names the file {value} by a relative path, which the "
                        "node resolves against its working directory (unknown statically); the ports listed in it "
                        "are unknown", "warning")
        return [replace(port, name=Unknown(f"{spec.entry} of {value} (a relative path)", at[0], at[1]))]
    read = _read(Path(value), param, at, diagnostics)
    if read is None:
        return [replace(port, name=Unknown(f"{spec.entry} of {value} (not read)", at[0], at[1]))]
    data, lines = read
    shown = workspace.display(value)
    entry = data.get(spec.entry) if isinstance(data, dict) else None
    if entry is None:
        if spec.default is not None:
            return [replace(port, name=spec.default)]
        diagnostics.add(shown, 1, "ports-file", f"{node.name} reads {spec.entry} from this file ({param}), which "
                        f"has none: no {port.kind.replace('_', ' ')} comes from it", "note")
        return []
    if isinstance(entry, str):
        return [replace(port, name=entry, file=shown, line=lines.get(spec.entry, [1])[0])]
    items = entry if isinstance(entry, list) else [entry]
    found = []
    for item, line in zip(items, lines.get(spec.entry, []) if isinstance(entry, list) else lines.get(spec.entry, [1])):
        name = (item.get(spec.field) if isinstance(item, dict) else None) if spec.field else item
        if isinstance(name, str) and name:
            found.append(replace(port, name=name, file=shown, line=line))
        else:
            what = f"an element without a string {spec.field}" if spec.field else "an element that is not a name"
            diagnostics.add(shown, line, "ports-file", f"{spec.entry} of this file ({param} of {node.name}) has "
                            f"{what}; it gives no {port.kind.replace('_', ' ')}", "warning")
    return found


def _read(path: Path, param: str, at: tuple[str, int],
          diagnostics: DiagnosticSink) -> tuple[object, dict[str, list[int]]] | None:
    """The file's YAML and, for each top-level key, the lines of its value (of each element of a
    list); None with a diagnostic at the parameter when it cannot be read."""
    try:
        loader = BoundedLoader(sandbox.read_text(path, "config"))
        try:
            root = loader.get_single_node()
            data = loader.construct_document(root) if root is not None else None
        finally:
            loader.dispose()
    except sandbox.Refused as exc:
        diagnostics.add(at[0], at[1], exc.code, f"{param} names a file that is not read ({exc}); the ports "
                        "listed in it are unknown", "warning")
        return None
    except budget.BudgetExceeded as exc:
        diagnostics.add(at[0], at[1], "budget-exceeded", f"{path} ({param}): {exc}; the ports listed in it are "
                        "unknown", "error")
        return None
    except (yaml.YAMLError, UnicodeDecodeError) as exc:
        diagnostics.add(at[0], at[1], "ports-file", f"{path} ({param}) is not valid YAML ({exc}); the ports listed "
                        "in it are unknown", "warning")
        return None
    lines: dict[str, list[int]] = {}
    for key, value in root.value if isinstance(root, yaml.MappingNode) else []:
        items = value.value if isinstance(value, yaml.SequenceNode) else [value]
        lines[str(key.value)] = [item.start_mark.line + 1 for item in items]
    return data, lines
