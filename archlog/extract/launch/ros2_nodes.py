"""The nodes and components of ROS 2 launch: their names, namespaces, remaps and parameters as
launch_ros passes them to each process."""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from contextlib import suppress
from dataclasses import replace
from pathlib import Path

from archlog import names
from archlog.extract.files import unreadable
from archlog.extract.launch.model import (
    Element,
    LaunchError,
    LaunchHost,
    LaunchNode,
    RefusedRead,
    SubstitutionError,
    UnknownArg,
    Unresolved,
    read_file,
    unresolved_code,
)
from archlog.extract.launch.ros2_actions import (
    Component,
    ParamFile,
    ParamSource,
    ParamText,
    Remap,
    Where,
)
from archlog.extract.launch.ros2_params import load_param_file
from archlog.extract.launch.ros2_subst import (
    Context,
    Parts,
    Rewritten,
    describe,
    parse,
    perform,
    text,
    typed_bool,
    unknown_reason,
    yaml_value,
)
from archlog.values import Unknown

_NODE_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_NAMESPACE = re.compile(r"/|(/[A-Za-z_][A-Za-z0-9_]*)+")


class Ros2Nodes:
    """Starts the nodes and components of ROS 2 launch actions in a host's configuration (sharing
    its element ids, workspace and diagnostics)."""

    def __init__(self, host: LaunchHost) -> None:
        self.host = host
        self.workspace = host.workspace
        self.diagnostics = host.diagnostics
        self.config = host.config
        self._param_files: dict[tuple[Path, str | None], list[tuple[str, str, object, Element]]] = {}
        self._templates: dict[Path, Parts] = {}  # parameter files read as substitutions
        self._launched: dict[int, str] = {}  # id of a container's Node action -> its full name

    def diag(self, where: Where, code: str, message: str, severity: str = "warning") -> None:
        self.diagnostics.add(self.host.display(where.file), where.line, code, message, severity)

    def hole(self, where: Where, code: str, message: str, severity: str = "warning") -> None:
        """A diagnostic for a part of the configuration not read (what it starts is unknown): the
        recovery summary counts it."""
        self.diag(where, code, message, severity)
        self.config.holes.append((self.host.display(where.file), where.line, message))

    def element(self, file: Path, line: int) -> Element:
        return self.host.element_at(file, line)

    # -- names, remaps and parameters ---------------------------------------------------
    def _base_name(self, name: Parts | None, where: Where, ctx: Context) -> str:
        """The node name the launch gives ("" for none, or when it is not known: then the source's
        name applies and a diagnostic says so)."""
        if name is None:
            return ""
        try:
            base = perform(name, ctx)
        except Unresolved as exc:
            self.diag(where, unresolved_code(exc, "launch-unknown"), f"node name not known statically ({exc}); "
                      "the name its source gives is used")
            return ""
        if not _NODE_NAME.fullmatch(base):
            raise LaunchError(f"invalid node name {base!r}")
        return base

    def _word(self, parts: Parts, ctx: Context) -> str:
        try:
            return perform(parts, ctx)
        except Unresolved:
            return describe(parts)

    def _ros_args(self, words: list[str], base: str, elem: Element, where: Where, ctx: Context
                  ) -> tuple[list[tuple[str, str, Element]], list[tuple[str, str, object, Element]], dict[str, str]]:
        """What `--ros-args` sections of a node's command line set: remaps (`-r`), parameters
        (`-p`, `--params-file`), and the name and namespace (`-r __node:=`, `-r __ns:=`)."""
        remaps: list[tuple[str, str, Element]] = []
        params: list[tuple[str, str, object, Element]] = []
        renamed: dict[str, str] = {}
        inside = False
        pending: str | None = None
        for word in words:
            if pending is not None:
                flag, pending = pending, None
                if flag in ("-r", "--remap") and ":=" in word:
                    src, dst = word.split(":=", 1)
                    node, _, src = src.rpartition(":") if src.count(":") == 1 else ("", "", src)
                    if node and base and node != base:
                        continue
                    if src in ("__node", "__name", "__ns"):
                        renamed.setdefault("__node" if src == "__name" else src, dst)
                    else:
                        remaps.append((src, dst, elem))
                elif flag in ("-p", "--param") and ":=" in word:
                    key, value = word.split(":=", 1)
                    params.append(("", key.rpartition(":")[2], yaml_value(value), elem))
                elif flag == "--params-file":
                    params.extend(self._param_file(ParamFile(text(word), where.line), where, ctx))
            elif word == "--ros-args":
                inside = True
            elif word == "--":
                inside = False
            elif inside and word in ("-r", "--remap", "-p", "--param", "--params-file", "--log-level", "-e",
                                     "--enclave", "--log-config-file"):
                pending = word
        return remaps, params, renamed

    def _scope_remaps(self, ctx: Context) -> list[tuple[str, str, Element]]:
        remaps = ctx.configs.get("ros_remaps")
        return list(remaps) if isinstance(remaps, list) else []

    def _remaps(self, remaps: tuple[Remap, ...], where: Where, ctx: Context) -> list[tuple[str, str, Element]]:
        found = []
        for remap in remaps:
            try:
                src, dst = perform(remap.src, ctx), perform(remap.dst, ctx)
            except Unresolved as exc:
                self.diag(replace(where, line=remap.line), unresolved_code(exc, "launch-unknown"),
                          f"remap skipped: {exc}")
                continue
            found.append((src, dst, self.element(where.file, remap.line)))
        return found

    def _scope_params(self, ctx: Context, component: str | None = None) -> list[tuple[str, str, object, Element]]:
        """set_parameter's values and set_parameters_from_file's entries (for a composable node,
        `component` is its key, see _for_component)."""
        found: list[tuple[str, str, object, Element]] = []
        entries = ctx.configs.get("global_params")
        for entry in entries if isinstance(entries, list) else []:
            if isinstance(entry, tuple):
                name, value, elem = entry
                found.append(("", name, value, elem))
            else:
                found.extend(entry if component is None else _for_component(entry, component))
        return found

    def _params(self, sources: tuple[ParamSource, ...], where: Where, ctx: Context, component: str | None = None
                ) -> list[tuple[str, str, object, Element]]:
        found: list[tuple[str, str, object, Element]] = []
        for source in sources:
            if isinstance(source, ParamFile):
                entries = self._param_file(source, where, ctx)
                found.extend(entries if component is None else _for_component(entries, component))
                continue
            for item in source.items:
                elem = self.element(where.file, item.line)
                try:
                    name = perform(item.name, ctx)
                except Unresolved as exc:
                    self.diag(replace(where, line=item.line), unresolved_code(exc, "launch-unknown"),
                              f"parameter skipped: {exc}")
                    self.config.params_unknown.append((elem, f"parameter skipped: {exc}"))
                    continue
                found.append(("", name, self._value(item.value, ctx, elem), elem))
        return found

    def _value(self, value: object, ctx: Context, elem: Element) -> object:
        """A parameter value as the node receives it; Unknown where it depends on the run, or
        where launch would reject it (then with an error)."""
        try:
            if isinstance(value, ParamText):
                return _typed(perform(value.parts, ctx), value.kind)
            if isinstance(value, list) and any(isinstance(v, ParamText) for v in value):
                return [self._value(v, ctx, elem) for v in value]
            return value
        except RefusedRead as exc:
            self.diagnostics.add(elem.file, elem.line, exc.code, f"parameter value not read: {exc}")
            return Unknown(str(exc), elem.file, elem.line)
        except Unresolved as exc:
            return Unknown(str(exc), elem.file, elem.line)
        except SubstitutionError as exc:
            self.diagnostics.add(elem.file, elem.line, "launch-subst", f"parameter value: {exc}", "error")
            return Unknown(str(exc), elem.file, elem.line)

    def _param_file(self, source: ParamFile, where: Where, ctx: Context) -> list[tuple[str, str, object, Element]]:
        """The entries of a parameter file (rewritten as nav2's RewrittenYaml does, when it is one)."""
        rewritten = source.path[0] if len(source.path) == 1 and isinstance(source.path[0], Rewritten) else None
        try:
            path = Path(perform(rewritten.source if rewritten else source.path, ctx))
        except Unresolved as exc:
            self.diag(replace(where, line=source.line), unresolved_code(exc, "launch-unknown"), f"parameter file not "
                      f"known statically ({exc}); its parameters are not part of this configuration")
            self.config.params_unknown.append((self.element(where.file, source.line), f"parameter file: {exc}"))
            return []
        if (refused := unreadable(path, "params")) is not None:
            missing = refused.code == "missing"
            self.diag(replace(where, line=source.line), "param-file" if missing else refused.code,
                      f"parameter file not found: {path}" if missing else f"parameter file skipped: {refused}")
            self.config.params_unknown.append((self.element(where.file, source.line), f"parameter file {path}"))
            return []
        substitute = source.allow_substs if isinstance(source.allow_substs, bool) else \
            typed_bool(perform(source.allow_substs, ctx))
        content = self._substituted(path, where, ctx) if substitute else None
        key = (Path(os.path.realpath(path)), content)
        if key not in self._param_files:
            shown = self.host.display(path)
            self._param_files[key] = [(pattern, name, value, self.element(path, line)) for pattern, name, value, line
                                      in load_param_file(path, shown, self.diagnostics, content)]
        entries = self._param_files[key]
        return _rewrite(entries, rewritten, ctx) if rewritten else entries

    def _substituted(self, path: Path, where: Where, ctx: Context) -> str | None:
        """A parameter file's text with its substitutions performed (allow_substs)."""
        try:
            key = Path(os.path.realpath(path))
            if key not in self._templates:
                self._templates[key] = parse(read_file(path, "params"))
            return perform(self._templates[key], ctx)
        except SubstitutionError as exc:
            self.diag(where, "param-file", f"substitutions in {path.name} not performed: {exc}")
            return None

    # -- components ---------------------------------------------------------------------
    def _component(self, component: Component, manager: str, ctx: Context) -> None:
        pkg, plugin = perform(component.pkg, ctx), perform(component.plugin, ctx)
        elem = self.element(component.where.file, component.where.line)
        base = self._base_name(component.name, component.where, ctx)
        namespace = node_namespace(component.namespace, ctx)
        full = names.join(namespace or "/", base) if base else ""
        remaps = self._scope_remaps(ctx) + self._remaps(component.remaps, component.where, ctx)
        key = f"{namespace.strip('/')}/{base}" if namespace and namespace != "/" else base
        params = self._scope_params(ctx, key) + self._params(component.params, component.where, ctx, key)
        self.config.nodes.append(LaunchNode(elem, pkg, plugin, full, namespace or "", remaps, ctx.condition,
                                            plugin=plugin, manager=manager, declared=full, chain=ctx.chain,
                                            parameters=params, ros2=True, guards=ctx.guards))


def value_or_unknown(parts: Parts, ctx: Context) -> str | UnknownArg:
    try:
        return perform(parts, ctx)
    except Unresolved as exc:
        return UnknownArg(str(exc))


def global_list(ctx: Context, key: str) -> list:
    """launch_ros's scope lists: taken from the configurations, created when absent."""
    current = ctx.configs.get(key)
    if not isinstance(current, list):
        current = []
        ctx.configs[key] = current
    return current


def namespace_config(ctx: Context) -> str | None:
    value = ctx.configs.get("ros_namespace")
    if isinstance(value, UnknownArg):
        raise Unresolved(f"the pushed namespace is not known ({unknown_reason('ros_namespace', value)})")
    return None if value is None else str(value)


def prefix(base: str | None, ns: str | None) -> str | None:
    """launch_ros's prefix_namespace: a relative `ns` goes under `base`, an absolute one stands alone."""
    if base is None and ns is None:
        return None
    if ns is None:
        combined = base
    elif not base or ns.startswith("/"):
        combined = ns
    else:
        combined = ("" if base == "/" else base) + "/" + ns
    return combined if combined == "/" else combined.rstrip("/")  # type: ignore[union-attr]


def absolute(ns: str | None) -> str | None:
    if ns is None:
        return None
    return ns if ns.startswith("/") else "/" + ns


def check_namespace(ns: str | None) -> None:
    if ns is not None and not _NAMESPACE.fullmatch(ns):
        raise LaunchError(f"invalid namespace {ns!r}")


def node_namespace(namespace: Parts | None, ctx: Context) -> str | None:
    """A node's namespace: its own under the pushed one; None when neither is set."""
    own = perform(namespace, ctx) if namespace is not None else None
    combined = absolute(own if own is not None and own.startswith("/") else prefix(namespace_config(ctx), own))
    check_namespace(combined)
    return combined


_COERCE: dict[str, Callable[[str], object]] = {"str": str, "int": int, "float": float, "bool": typed_bool}


def _typed(value: str, kind: str | None) -> object:
    """A performed parameter value coerced as launch's typed parameter values are."""
    if kind is None:
        return yaml_value(value if value else "''")
    if kind.startswith("list_of_"):
        loaded = yaml_value(value)
        if not isinstance(loaded, list):
            raise SubstitutionError(f"{value!r} is not a list")
        return [v if kind == "list_of_str" and isinstance(v, str) else _typed(str(v), kind[8:]) for v in loaded]
    if kind not in _COERCE:
        raise SubstitutionError(f"unknown parameter type {kind!r}")
    try:
        return _COERCE[kind](value)
    except ValueError:
        raise SubstitutionError(f"{value!r} is not a {kind}") from None


def _for_component(entries: list[tuple[str, str, object, Element]], key: str
                   ) -> list[tuple[str, str, object, Element]]:
    """A parameter file as launch_ros applies it to a composable node before loading it: the
    `/**` entries, then those under the node's own key (`namespace/name`, no other wildcard),
    given to the node directly (pattern "")."""
    def normal(pattern: str) -> str:
        return "/".join(part for part in pattern.split("/") if part)

    return [("", name, value, elem) for wanted in ("**", key) for pattern, name, value, elem in entries
            if normal(pattern) == wanted and (wanted == "**" or key)]


def _rewrite(entries: list[tuple[str, str, object, Element]], rewritten: Rewritten, ctx: Context
             ) -> list[tuple[str, str, object, Element]]:
    """nav2_common's RewrittenYaml over loaded entries: leaf parameters renamed by `params`,
    values equal to a key of `values` replaced, every node key put under `root_key`."""
    def resolved(parts: Parts, elem: Element) -> object:
        """A rewritten value converted as RewrittenYaml converts it."""
        try:
            value = perform(parts, ctx)
        except Unresolved as exc:
            return Unknown(str(exc), elem.file, elem.line)
        if rewritten.convert_types:
            with suppress(ValueError):
                return float(value) if "." in value else int(value)
        return {"true": True, "false": False}.get(value.lower(), value)

    root = perform(rewritten.root_key, ctx) if rewritten.root_key is not None else ""
    params, values = dict(rewritten.params), dict(rewritten.values)
    out = []
    for pattern, name, value, elem in entries:
        if name.rpartition(".")[2] in params:
            value = resolved(params[name.rpartition(".")[2]], elem)
        elif f"{pattern}.ros__parameters.{name}" in params:
            value = resolved(params[f"{pattern}.ros__parameters.{name}"], elem)
        elif not isinstance(value, (dict, list)) and str(value) in values:
            value = resolved(values[str(value)], elem)
        out.append((f"{root.strip('/')}/{pattern.lstrip('/')}" if root.strip("/") else pattern, name, value, elem))
    return out

