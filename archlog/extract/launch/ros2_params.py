"""ROS 2 parameter files (`--params-file`): the `node: ros__parameters:` layout and node-key matching.

The layout is rcl_yaml_param_parser's: the mapping keys above `ros__parameters` form the node
key (joined with `/`, so `ns: {talker: {ros__parameters: ...}}` is `ns/talker`), the keys below it
form dotted parameter names. A node key may hold wildcards; `matches` decides whether it applies
to a node as rclcpp does (`parameter_map_from`). A file is read within the budget (aliases count
at the size they expand to), a crossing being at its line in the file.
"""

from __future__ import annotations

import re
from pathlib import Path

import yaml

from archlog import budget, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.bounded_yaml import BoundedLoader, crossing_in

PARAMS_KEY = "ros__parameters"
Entry = tuple[str, str, object, int]


def load_param_file(path: Path, shown: str, diagnostics: DiagnosticSink, text: str | None = None) -> list[Entry]:
    """Every parameter of a parameter file as (node key, dotted name, value, line), in file order;
    `text` replaces the file's content (a file whose substitutions were performed). Problems are
    diagnostics at `shown`:line and the entries found so far are kept."""
    if text is None:
        try:
            text = sandbox.read_text(path, "params")
        except sandbox.Refused as exc:
            diagnostics.add(shown, 1, exc.code, f"cannot read parameter file: {exc}", "error")
            return []
    with budget.scope():
        try:
            loader = BoundedLoader(text)
        except yaml.YAMLError as exc:  # a character YAML does not allow (NUL, ...)
            diagnostics.add(shown, 1, "param-file", f"invalid YAML: {exc}", "error")
            return []
        with crossing_in(loader, shown):
            try:
                root = loader.get_single_node()
            except yaml.YAMLError as exc:
                mark = getattr(exc, "problem_mark", None)
                diagnostics.add(shown, mark.line + 1 if mark else 1, "param-file", f"invalid YAML: {exc}", "error")
                return []
            finally:
                loader.dispose()
    if root is None:
        return []
    entries: list[Entry] = []
    _nodes(root, [], loader, entries, shown, diagnostics)
    return entries


def _nodes(node: yaml.Node, keys: list[str], loader: yaml.SafeLoader, entries: list[Entry], shown: str,
           diagnostics: DiagnosticSink) -> None:
    """Walk the node-key levels down to each `ros__parameters`."""
    if not isinstance(node, yaml.MappingNode):
        diagnostics.add(shown, node.start_mark.line + 1, "param-file",
                        f"expected a mapping of node names{' under ' + '/'.join(keys) if keys else ''}", "error")
        return
    for key_node, value in node.value:
        key = str(loader.construct_object(key_node))
        if key == PARAMS_KEY:
            if not keys:
                diagnostics.add(shown, key_node.start_mark.line + 1, "param-file",
                                "ros__parameters must be under a node name", "error")
            elif isinstance(value, yaml.MappingNode):
                _params(value, "/".join(keys), "", loader, entries, shown, diagnostics)
            elif not (isinstance(value, yaml.ScalarNode) and value.value in ("", "~", "null")):
                diagnostics.add(shown, value.start_mark.line + 1, "param-file",
                                "ros__parameters must be a mapping of parameter names", "error")
        else:
            _nodes(value, [*keys, key.strip("/") if keys else key.rstrip("/")], loader, entries, shown, diagnostics)


def _params(node: yaml.MappingNode, pattern: str, prefix: str, loader: yaml.SafeLoader, entries: list[Entry],
            shown: str, diagnostics: DiagnosticSink) -> None:
    """Parameters below ros__parameters: nested mappings become dotted names."""
    for key_node, value in node.value:
        name = f"{prefix}{loader.construct_object(key_node)}"
        if isinstance(value, yaml.MappingNode):
            _params(value, pattern, name + ".", loader, entries, shown, diagnostics)
            continue
        try:
            entries.append((pattern, name, loader.construct_object(value, deep=True), value.start_mark.line + 1))
        except yaml.YAMLError as exc:
            diagnostics.add(shown, value.start_mark.line + 1, "param-file", f"invalid value for {name}: {exc}", "error")


def matches(pattern: str, node_fqn: str) -> bool:
    """Whether a parameter file's node key applies to the node `node_fqn` (rclcpp's rule: a key
    without a leading `/` gets one; then `/*` matches one name token and `/**` any number of them,
    the rest of the key being a regular expression that must match the whole name)."""
    key = pattern if pattern.startswith("/") else "/" + pattern
    try:
        return re.fullmatch(key.replace("/*", r"(/\w+)"), node_fqn, re.ASCII) is not None
    except re.error:
        return False
