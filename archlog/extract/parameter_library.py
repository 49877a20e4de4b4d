"""Parameters declared through generate_parameter_library: the package's YAML definition file.

A package's CMakeLists.txt calls `generate_parameter_library(TARGET path/x_parameters.yaml)`; an
executable linking TARGET (directly or through the package's libraries) declares every parameter
of that file when its code makes the generated ParamListener, whose header is built, never in the
workspace. The file's top key is the C++ namespace of the generated struct; below it, nested
mappings are namespaces joined with `.` and a mapping with `type` is a parameter:
`{type, default_value, read_only, validation: {bounds<>: [lo, hi], one_of<>: [[...]], ...}}`.
A parameter without `default_value` must be set. A `__map_` key declares parameters under names
read from another parameter: the node then declares dynamically.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import yaml

from archlog import sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch import bounded_yaml
from archlog.extract.summary import NodeSummary, ParamSpec, Port

TYPES = {"bool": "bool", "int": "integer", "double": "double", "string": "string", "bool_array": "bool_array",
         "int_array": "integer_array", "double_array": "double_array", "string_array": "string_array"}
BOUNDS = {"bounds": (">=", "<="), "lower_bounds": (">=",), "upper_bounds": ("<=",), "gt": (">",), "lt": ("<",),
          "gt_eq": (">=",), "lt_eq": ("<=",)}  # validator -> the comparison of each of its arguments


class DefinitionError(Exception):
    """A definition file that does not parse or is not shaped as one; `line` is where."""

    def __init__(self, line: int, message: str) -> None:
        super().__init__(message)
        self.line = line


def load(path: Path) -> tuple[str, dict[str, dict], dict[str, int]]:
    """A definition file's C++ namespace, its parameters by dotted name, and the line of each
    parameter's own key; raises sandbox.Refused or DefinitionError."""
    text = sandbox.read_text(path, "params")
    try:
        document = bounded_yaml.load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        raise DefinitionError(mark.line + 1 if mark else 1, f"does not parse: {exc}") from None
    if not isinstance(document, dict) or len(document) != 1 or not isinstance(next(iter(document.values())), dict):
        raise DefinitionError(1, "has not one top key (the C++ namespace) holding the parameters")
    namespace, tree = next(iter(document.items()))
    lines = _key_lines(text)
    found = dict(_parameters(tree, ""))
    return str(namespace), found, {name: lines.get(name.rsplit(".", 1)[-1], 1) for name in found}


def add_declarations(summary: NodeSummary, files: list[Path], display, diagnostics: DiagnosticSink) -> None:
    """Give `summary` the parameters its linked parameter libraries declare (a file that cannot be
    read is a diagnostic and makes the node's parameters dynamic: some names are not known)."""
    for path in files:
        shown = display(path)
        try:
            _namespace, found, lines = load(path)
        except (sandbox.Refused, DefinitionError) as exc:
            line = exc.line if isinstance(exc, DefinitionError) else 1
            diagnostics.add(shown, line, "param-library", f"parameter library definition {exc}"
                            if isinstance(exc, DefinitionError) else f"parameter library definition not read: {exc}",
                            "warning")
            summary.params_dynamic = summary.params_dynamic or f"{shown}:{line}: its parameter library is not read"
            continue
        for name, entry in found.items():
            if "__map_" in name:
                summary.params_dynamic = summary.params_dynamic or \
                    f"{shown}:{lines[name]}: a parameter library declares parameters under names other parameters give"
                continue
            default = entry.get("default_value")
            summary.ports.append(Port("param_read", name, "", shown, lines[name],
                                      default=None if default is None else _text(default), param=_spec(entry)))


def _parameters(tree: dict, prefix: str) -> Iterator[tuple[str, dict]]:
    for key, value in tree.items():
        if not isinstance(value, dict):
            continue
        name = f"{prefix}{key}"
        if "type" in value and not isinstance(value["type"], dict):
            yield name, value
        else:
            yield from _parameters(value, f"{name}.")


def _spec(entry: dict) -> ParamSpec:
    declared = str(entry.get("type", ""))
    base = declared.replace("_fixed", "").rsplit("_", 1)[0] if "_fixed" in declared else declared
    if base == "string_fixed":
        base = "string"
    bounds: list[tuple[str, str]] = []
    choices: tuple[str, ...] = ()
    validation = entry.get("validation")
    for key, args in (validation.items() if isinstance(validation, dict) else ()):
        validator = str(key).removesuffix("<>").rsplit("::", 1)[-1]
        values = args if isinstance(args, list) else [args]
        if validator in BOUNDS and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
            bounds += [(op, _text(v)) for op, v in zip(BOUNDS[validator], values)]
        elif validator == "one_of" and values and isinstance(values[0], list):
            choices = tuple(_text(v) for v in values[0])
    return ParamSpec(TYPES.get(base, ""), "default_value" not in entry, entry.get("read_only") is True,
                     tuple(bounds), choices, declared=True)


def _text(value: object) -> str:
    """A YAML value as the facts write a default: booleans lower case, lists as written."""
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def _key_lines(text: str) -> dict[str, int]:
    """The line where each key is first written (a parameter is reported at its own key)."""
    lines: dict[str, int] = {}
    for number, line in enumerate(text.splitlines(), 1):
        key = line.strip().split(":", 1)[0].strip("'\" ")
        if line.strip().endswith(":") or ": " in line:
            lines.setdefault(key, number)
    return lines
