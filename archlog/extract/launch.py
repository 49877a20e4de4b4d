"""Interpret ROS 1 launch XML as roslaunch does: args, groups, includes, remaps, params, nodes."""

from __future__ import annotations

import shlex
from dataclasses import dataclass, field
from pathlib import Path

import yaml
from lxml import etree

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.substitution import SubstContext, SubstitutionError, substitute
from archlog.extract.workspace import Workspace
from archlog.values import Unknown

MAX_INCLUDE_DEPTH = 32


@dataclass
class Element:
    """A launch element that facts can point at."""

    id: str
    file: str
    line: int


@dataclass
class LaunchNode:
    """A node instance declared by a launch file (or given by rosrun)."""

    elem: Element
    pkg: str
    type: str
    name: str
    namespace: str
    remaps: list[tuple[str, str, Element]] = field(default_factory=list)
    condition: str | None = None


@dataclass
class LaunchConfig:
    """The system configuration: node instances and parameter values."""

    nodes: list[LaunchNode] = field(default_factory=list)
    params: dict[str, tuple[object, Element]] = field(default_factory=dict)


@dataclass
class _Scope:
    ns: str
    ctx: SubstContext
    remaps: list[tuple[str, str, Element]]
    depth: int = 0


class LaunchInterpreter:
    """Loads one or more launch files into a single LaunchConfig, reporting problems as diagnostics."""

    def __init__(self, workspace: Workspace, diagnostics: DiagnosticSink) -> None:
        self.workspace = workspace
        self.diagnostics = diagnostics
        self.config = LaunchConfig()
        self._count = 0
        self._anon: dict[str, str] = {}

    def load(self, files: list[Path], args: dict[str, str]) -> LaunchConfig:
        for path in files:
            ctx = SubstContext(dict(args), self.workspace.find, path, self._anon)
            self._file(path, _Scope("/", ctx, []), passed=set(args), strict=False)
        return self.config

    # -- helpers --------------------------------------------------------------------------
    def _element(self, file: Path, el: etree._Element) -> Element:
        self._count += 1
        return Element(f"e{self._count:05d}", self.workspace.display(file), el.sourceline or 1)

    def _diag(self, file: Path, el: etree._Element | None, code: str, message: str, severity: str = "error") -> None:
        line = el.sourceline if el is not None and el.sourceline else 1
        self.diagnostics.add(self.workspace.display(file), line, code, message, severity)

    def _attr(self, scope: _Scope, el: etree._Element, key: str, default: str | None = None) -> str | None:
        raw = el.get(key)
        if raw is None:
            return default
        return substitute(raw, scope.ctx)

    def _enabled(self, scope: _Scope, el: etree._Element) -> bool | str:
        """True/False, or the raw condition text when it cannot be resolved statically."""
        for key, want in (("if", True), ("unless", False)):
            raw = el.get(key)
            if raw is None:
                continue
            try:
                value = substitute(raw, scope.ctx).strip().lower()
            except SubstitutionError:
                return f"{key}={raw}"
            if value not in ("true", "1", "false", "0"):
                raise SubstitutionError(f"{key}=\"{raw}\" is not a boolean ({value!r})")
            if (value in ("true", "1")) != want:
                return False
        return True

    # -- files and children ---------------------------------------------------------------
    def _file(self, path: Path, scope: _Scope, passed: set[str], strict: bool) -> None:
        shown = self.workspace.display(path)
        try:
            root = etree.parse(str(path), etree.XMLParser(remove_comments=True)).getroot()
        except etree.XMLSyntaxError as exc:
            self.diagnostics.add(shown, exc.lineno or 1, "launch-xml", f"malformed launch XML: {exc.msg}", "error")
            return
        except OSError as exc:
            self.diagnostics.add(shown, 1, "launch-missing", f"cannot read launch file: {exc}", "error")
            return
        if root.tag != "launch":
            self._diag(path, root, "launch-xml", f"root element is <{root.tag}>, not <launch>")
            return
        self._children(path, root, scope, passed)
        unused = passed - set(scope.ctx.args_declared) if strict else set()
        for name in sorted(unused):
            self._diag(path, root, "launch-arg", f"arg '{name}' passed by the include is not declared in this file")

    def _children(self, path: Path, parent: etree._Element, scope: _Scope, passed: set[str]) -> None:
        for el in parent:
            if not isinstance(el.tag, str):
                continue
            try:
                enabled = self._enabled(scope, el)
                if enabled is False:
                    continue
                handler = getattr(self, f"_tag_{el.tag.replace('-', '_')}", None)
                if handler is None:
                    if el.tag not in ("machine", "env", "master"):
                        self._diag(path, el, "launch-tag", f"unknown tag <{el.tag}> ignored", "warning")
                    continue
                condition = None if enabled is True else enabled
                if condition:
                    self._diag(path, el, "launch-condition",
                               f"condition {condition} cannot be resolved statically; element kept as conditional",
                               "note")
                handler(path, el, scope, passed, condition)
            except SubstitutionError as exc:
                self._diag(path, el, "launch-subst", f"<{el.tag}>: {exc}")

    def _tag_arg(self, path: Path, el: etree._Element, scope: _Scope, passed: set[str], _c: str | None) -> None:
        name = el.get("name")
        if not name:
            raise SubstitutionError("<arg> needs a name")
        scope.ctx.args_declared.add(name)
        if el.get("value") is not None:
            if name in passed:
                self._diag(path, el, "launch-arg", f"arg '{name}' has a value and cannot be overridden", "warning")
            scope.ctx.args[name] = self._attr(scope, el, "value") or ""
        elif name not in passed and el.get("default") is not None:
            scope.ctx.args[name] = self._attr(scope, el, "default") or ""

    def _tag_group(self, path: Path, el: etree._Element, scope: _Scope, passed: set[str], _c: str | None) -> None:
        ns = self._attr(scope, el, "ns")
        child = _Scope(names.join(scope.ns, ns) if ns else scope.ns, scope.ctx, list(scope.remaps), scope.depth)
        self._children(path, el, child, passed)

    def _tag_remap(self, path: Path, el: etree._Element, scope: _Scope, _p: set[str], _c: str | None) -> None:
        src, dst = self._attr(scope, el, "from"), self._attr(scope, el, "to")
        if not src or not dst:
            raise SubstitutionError("<remap> needs 'from' and 'to'")
        scope.remaps.append((src, dst, self._element(path, el)))

    def _tag_include(self, path: Path, el: etree._Element, scope: _Scope, passed: set[str], _c: str | None) -> None:
        target = Path(self._attr(scope, el, "file") or "")
        if scope.depth >= MAX_INCLUDE_DEPTH:
            self._diag(path, el, "launch-include", "include nesting too deep (a cycle?)")
            return
        if not target.is_file():
            self._diag(path, el, "launch-include", f"included file not found: {target}")
            return
        args: dict[str, str] = dict(scope.ctx.args) if el.get("pass_all_args", "").lower() == "true" else {}
        for child in el:
            if child.tag == "arg" and self._enabled(scope, child) is True:
                value = self._attr(scope, child, "value", self._attr(scope, child, "default"))
                args[child.get("name", "")] = value or ""
        ns = self._attr(scope, el, "ns")
        ctx = SubstContext(args, self.workspace.find, target, self._anon, scope.ctx.env)
        child_scope = _Scope(names.join(scope.ns, ns) if ns else scope.ns, ctx, list(scope.remaps), scope.depth + 1)
        for child in el:
            if child.tag == "remap":
                self._tag_remap(path, child, child_scope, set(), None)
        self._file(target, child_scope, set(args), strict=el.get("pass_all_args", "").lower() != "true")

    def _tag_node(self, path: Path, el: etree._Element, scope: _Scope, _p: set[str], condition: str | None) -> None:
        pkg, exe = self._attr(scope, el, "pkg"), self._attr(scope, el, "type")
        name = self._attr(scope, el, "name") or self._attr(scope, el, "test-name")
        if not (pkg and exe and name):
            raise SubstitutionError(f"<{el.tag}> needs pkg, type and name")
        elem = self._element(path, el)
        ns = names.join(scope.ns, self._attr(scope, el, "ns") or "")
        remaps = list(scope.remaps)
        for word in shlex.split(self._attr(scope, el, "args") or ""):
            if ":=" not in word:
                continue
            key, value = word.split(":=", 1)
            if key == "__name":
                name = value
            elif key == "__ns":
                ns = names.join("/", value)
            elif key.startswith("_") and not key.startswith("__"):
                self.config.params[names.join(names.join(ns, name), key[1:])] = (_auto(value), elem)
            elif not key.startswith("__"):
                remaps.append((key, value, elem))
        node = LaunchNode(elem, pkg, exe, names.join(ns, name), ns, remaps, condition)
        node_scope = _Scope(node.name, scope.ctx, node.remaps, scope.depth)
        for child in el:
            if not isinstance(child.tag, str):
                continue
            try:
                if self._enabled(scope, child) is not True:
                    continue
                if child.tag == "remap":
                    self._tag_remap(path, child, node_scope, set(), None)
                elif child.tag in ("param", "rosparam"):
                    getattr(self, f"_tag_{child.tag}")(path, child, node_scope, set(), None)
            except SubstitutionError as exc:
                self._diag(path, child, "launch-subst", f"<{child.tag}>: {exc}")
        self.config.nodes.append(node)

    _tag_test = _tag_node

    def _tag_param(self, path: Path, el: etree._Element, scope: _Scope, _p: set[str], _c: str | None) -> None:
        name = self._attr(scope, el, "name")
        if not name:
            raise SubstitutionError("<param> needs a name")
        elem = self._element(path, el)
        if el.get("value") is not None:
            value = _coerce(self._attr(scope, el, "value") or "", el.get("type"))
        elif el.get("textfile") is not None:
            value = _read(Path(self._attr(scope, el, "textfile") or ""))
        else:
            source = "command" if el.get("command") is not None else "binfile"
            value = Unknown(f"{source}: {el.get(source)}", elem.file, elem.line)
        self.config.params[names.join(scope.ns, name)] = (value, elem)

    def _tag_rosparam(self, path: Path, el: etree._Element, scope: _Scope, _p: set[str], _c: str | None) -> None:
        command = el.get("command", "load")
        ns = names.join(scope.ns, self._attr(scope, el, "ns") or "")
        target = names.join(ns, self._attr(scope, el, "param") or "")
        elem = self._element(path, el)
        if command == "delete":
            for key in [k for k in self.config.params if k == target or k.startswith(target.rstrip("/") + "/")]:
                del self.config.params[key]
            return
        if command != "load":
            return
        text = _read(Path(self._attr(scope, el, "file") or "")) if el.get("file") else (el.text or "")
        if el.get("subst_value", "").lower() == "true":
            text = substitute(text, scope.ctx)
        try:
            data = yaml.safe_load(text) if text.strip() else None
        except yaml.YAMLError as exc:
            raise SubstitutionError(f"rosparam YAML does not parse: {exc}") from None
        for key, value in _flatten(target, data):
            self.config.params[key] = (value, elem)


def _auto(text: str) -> object:
    for convert in (int, float):
        try:
            return convert(text)
        except ValueError:
            continue
    lowered = text.strip().lower()
    return {"true": True, "false": False}.get(lowered, text)


def _coerce(text: str, kind: str | None) -> object:
    if kind in (None, "auto"):
        return _auto(text)
    if kind in ("str", "string"):
        return text
    if kind == "yaml":
        return yaml.safe_load(text)
    try:
        if kind == "int":
            return int(text.strip())
        if kind == "double":
            return float(text.strip())
        if kind in ("bool", "boolean"):
            return {"true": True, "1": True, "false": False, "0": False}[text.strip().lower()]
    except (ValueError, KeyError):
        raise SubstitutionError(f"param value {text!r} is not of type {kind}") from None
    raise SubstitutionError(f"unknown param type {kind!r}")


def _read(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8")
    except OSError as exc:
        raise SubstitutionError(f"cannot read {path}: {exc.strerror}") from None


def _flatten(prefix: str, data: object) -> list[tuple[str, object]]:
    if isinstance(data, dict) and data:
        return [kv for key, value in data.items() for kv in _flatten(names.join(prefix, str(key)), value)]
    return [(prefix, data)] if data is not None else []
