"""Interpret ROS 1 launch XML exactly as roslaunch 1.15 loads it (without running anything).

Scoping follows roslaunch's LoaderContext: a `<group>` copies the args and private params of
its parent, an `<include>` starts a fresh arg scope fed by its `<arg>` children (or by
pass_all_args), remaps apply to nodes declared after them in the same scope and below, and
`~param`s outside a node apply to every node declared after them in that scope. Where roslaunch
would stop with an error, archlog reports a diagnostic at the element and goes on.
"""

from __future__ import annotations

import shlex
from dataclasses import dataclass, field, replace
from pathlib import Path

import yaml
from lxml import etree

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.substitution import (SubstContext, SubstitutionError, UnknownArg, Unresolved, auto_value,
                                          substitute)
from archlog.extract.workspace import Workspace
from archlog.values import Unknown

MAX_INCLUDE_DEPTH = 32
NODE_ATTRS = {"pkg", "type", "machine", "name", "args", "output", "respawn", "respawn_delay", "cwd", "ns",
              "clear_params", "launch-prefix", "required", "if", "unless"}


class LaunchError(Exception):
    """An element roslaunch would reject."""


@dataclass(frozen=True)
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
    args: str = ""
    plugin: str | None = None
    manager: str | None = None


@dataclass
class LaunchConfig:
    """The system configuration: node instances and parameter values."""

    nodes: list[LaunchNode] = field(default_factory=list)
    params: dict[str, tuple[object, Element]] = field(default_factory=dict)


@dataclass
class _Scope:
    """roslaunch's LoaderContext: namespace, args, remaps and private params of one scope."""

    ns: str
    subst: SubstContext
    declared: list[str]
    remaps: list[tuple[str, str, Element]]
    private: list[tuple[str, object, Element]]
    condition: str | None = None
    pass_all_args: bool = False
    depth: int = 0

    def child(self, ns: str | None) -> "_Scope":
        """A group scope: args, declared names and remaps copied, the private-param list shared."""
        return replace(self, ns=_child_ns(self.ns, ns), subst=self.subst.child(), declared=list(self.declared),
                       remaps=list(self.remaps))

    def add_remap(self, src: str, dst: str, elem: Element) -> None:
        src, dst = names.canonical(src), names.canonical(dst)
        if not src or not dst:
            raise LaunchError("remap from/to attributes cannot be empty")
        for value in (src, dst):
            if not names.is_valid(value):
                raise LaunchError(f"remap name [{value}] is not a valid ROS name")
        self.remaps = [r for r in self.remaps if r[0] != src] + [(src, dst, elem)]


def _child_ns(ns: str, sub: str | None) -> str:
    if not sub:
        return ns
    if sub.startswith("/"):
        return names.canonical(sub)
    if sub == "~":
        return "~"
    return names.join(ns, sub)


class LaunchInterpreter:
    """Loads one or more launch files into a single LaunchConfig, reporting problems as diagnostics."""

    def __init__(self, workspace: Workspace, diagnostics: DiagnosticSink) -> None:
        self.workspace = workspace
        self.diagnostics = diagnostics
        self.config = LaunchConfig()
        self._count = 0
        self._anon: dict[str, str] = {}
        self._node_names: dict[str, Element] = {}

    def load(self, files: list[Path], args: dict[str, str]) -> LaunchConfig:
        for path in files:
            subst = SubstContext(dict(args), self.workspace.find, path, self._anon)
            self._file(path, _Scope("/", subst, [], [], []))
        return self.config

    # -- helpers --------------------------------------------------------------------------
    def _element(self, file: Path, el: etree._Element) -> Element:
        self._count += 1
        return Element(f"e{self._count:05d}", self.workspace.display(file), el.sourceline or 1)

    def _diag(self, file: Path, el: etree._Element | None, code: str, message: str, severity: str = "error") -> None:
        line = el.sourceline if el is not None and el.sourceline else 1
        self.diagnostics.add(self.workspace.display(file), line, code, message, severity)

    @staticmethod
    def _attr(scope: _Scope, el: etree._Element, key: str) -> str | None:
        raw = el.get(key)
        return None if raw is None else substitute(raw, scope.subst)

    def _required(self, scope: _Scope, el: etree._Element, key: str) -> str:
        if el.get(key) is None:
            raise LaunchError(f"<{el.tag}> is missing the required attribute '{key}'")
        return self._attr(scope, el, key) or ""

    def _enabled(self, scope: _Scope, el: etree._Element) -> bool | str:
        """True/False, or the condition text when it cannot be resolved statically."""
        if el.get("if") is not None and el.get("unless") is not None:
            raise LaunchError("cannot set both 'if' and 'unless' on the same tag")
        for key, want in (("if", True), ("unless", False)):
            raw = el.get(key)
            if raw is None:
                continue
            try:
                value = substitute(raw, scope.subst)
            except Unresolved as exc:
                return f'{key}="{raw}" ({exc})'
            return _bool(value, key) == want
        return True

    # -- files and children ---------------------------------------------------------------
    def _file(self, path: Path, scope: _Scope) -> bool:
        """Load a file into the scope; False when it could not be read at all."""
        shown = self.workspace.display(path)
        try:
            root = etree.parse(str(path), etree.XMLParser(remove_comments=True)).getroot()
        except etree.XMLSyntaxError as exc:
            self.diagnostics.add(shown, exc.lineno or 1, "launch-xml", f"malformed launch XML: {exc.msg}", "error")
            return False
        except OSError as exc:
            self.diagnostics.add(shown, 1, "launch-missing", f"cannot read launch file: {exc}", "error")
            return False
        if root.tag != "launch":
            self._diag(path, root, "launch-xml", f"root element is <{root.tag}>, not <launch> (a ROS 2 file?)")
            return False
        self._children(path, root, scope)
        return True

    def _children(self, path: Path, parent: etree._Element, scope: _Scope) -> None:
        for el in parent:
            if not isinstance(el.tag, str):
                continue
            handler = getattr(self, f"_tag_{el.tag}", None)
            if handler is None:
                if el.tag not in ("machine", "env", "master"):
                    self._diag(path, el, "launch-tag", f"unrecognized tag <{el.tag}> ignored", "warning")
                continue
            try:
                enabled = self._enabled(scope, el)
                if enabled is False:
                    continue
                if enabled is not True:
                    self._conditional(path, el, enabled)
                handler(path, el, scope if enabled is True else replace(scope, condition=enabled))
            except Unresolved as exc:
                self._diag(path, el, "launch-unresolved",
                           f"<{el.tag}> skipped: {exc}; pass the value with --arg or set it in the environment",
                           "warning")
            except (SubstitutionError, LaunchError) as exc:
                self._diag(path, el, "launch-subst" if isinstance(exc, SubstitutionError) else "launch-invalid",
                           f"<{el.tag}>: {exc}")

    def _conditional(self, path: Path, el: etree._Element, condition: str) -> None:
        self._diag(path, el, "launch-condition",
                   f"condition {condition} cannot be resolved statically; <{el.tag}> kept as conditional", "note")

    def _tag_arg(self, path: Path, el: etree._Element, scope: _Scope,
                 target: dict[str, str | UnknownArg] | None = None) -> None:
        """Declare an arg; values resolve in `scope` and are stored in `target` (an include's
        passed args) or in the scope's own args."""
        name = self._required(scope, el, "name")
        if el.get("value") is not None and el.get("default") is not None:
            raise LaunchError("<arg> must have only one of value/default")
        if name in scope.declared and not scope.pass_all_args:
            raise LaunchError(f"arg '{name}' has already been declared")
        if name not in scope.declared:
            scope.declared.append(name)
        args = scope.subst.args if target is None else target
        for key in ("value", "default"):
            if el.get(key) is None or (key == "default" and name in args):
                continue
            if key == "value" and name in args and not scope.pass_all_args:
                raise LaunchError(f"cannot override arg '{name}', which has already been set")
            try:
                args[name] = self._attr(scope, el, key) or ""
            except Unresolved as exc:
                args[name] = UnknownArg(str(exc))
                self._diag(path, el, "launch-arg-unknown", f"arg '{name}' is not known statically: {exc}", "note")

    def _tag_group(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        child = scope.child(self._ns_attr(scope, el))
        child.private = list(scope.private)
        self._clear_params(scope, el, child.ns, is_node=False)
        self._children(path, el, child)

    def _ns_attr(self, scope: _Scope, el: etree._Element) -> str | None:
        ns = self._attr(scope, el, "ns")
        if ns is not None and not ns:
            raise LaunchError(f"<{el.tag}> has an empty 'ns' attribute")
        return ns

    def _clear_params(self, scope: _Scope, el: etree._Element, ns: str, is_node: bool) -> None:
        value = self._attr(scope, el, "clear_params")
        if value and _bool(value, "clear_params") and not is_node and el.get("ns") is None:
            raise LaunchError("'ns' attribute must be set in order to use 'clear_params'")

    def _tag_remap(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        scope.add_remap(self._required(scope, el, "from"), self._required(scope, el, "to"), self._element(path, el))

    def _tag_include(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        target = Path(self._required(scope, el, "file"))
        pass_all = _bool(self._attr(scope, el, "pass_all_args") or "false", "pass_all_args")
        if scope.depth >= MAX_INCLUDE_DEPTH:
            raise LaunchError("include nesting too deep (a cycle?)")
        ns = self._ns_attr(scope, el)
        self._clear_params(scope, el, _child_ns(scope.ns, ns), is_node=False)
        passed: dict[str, str | UnknownArg] = dict(scope.subst.args) if pass_all else {}
        declared: list[str] = list(passed)
        for child in el:
            if not isinstance(child.tag, str) or child.tag == "env":
                continue
            if child.tag != "arg":
                self._diag(path, child, "launch-tag", f"<{child.tag}> inside <include> is ignored by roslaunch",
                           "warning")
                continue
            if self._enabled(scope, child) is not True:
                continue
            self._tag_arg(path, child, replace(scope, declared=declared, pass_all_args=pass_all), passed)
        missing = [a for a in declared if a not in passed]
        if missing:
            raise LaunchError(f"include args must have declared values: {', '.join(missing)}")
        if not target.is_file():
            self._diag(path, el, "launch-include", f"included file not found: {target}")
            return
        child_scope = _Scope(_child_ns(scope.ns, ns), scope.subst.child(args=passed, file=target), [],
                             list(scope.remaps), scope.private, scope.condition, pass_all, scope.depth + 1)
        if self._file(target, child_scope) and not pass_all:
            unused = [a for a in passed if a not in child_scope.declared]
            if unused:
                raise LaunchError(f"unused args [{', '.join(unused)}] for include of [{target}]")

    def _tag_param(self, path: Path, el: etree._Element, scope: _Scope, node_ns: str | None = None) -> None:
        name = self._required(scope, el, "name").strip()
        elem = self._element(path, el)
        sources = [k for k in ("value", "textfile", "binfile", "command") if el.get(k) is not None]
        if len(sources) != 1:
            raise LaunchError("<param> must have one and only one of value/textfile/binfile/command")
        kind = (el.get("type") or "auto").lower().strip()
        try:
            value = self._param_value(scope, el, sources[0], kind, elem)
        except Unresolved as exc:
            value = Unknown(f"{el.get(sources[0])} ({exc})", elem.file, elem.line)
        if node_ns is not None or name.startswith("~"):
            if node_ns is not None:
                self._set_param(names.canonical(f"{node_ns}/{name.lstrip('~')}"), value, elem)
            else:
                scope.private.append((name, value, elem))
        else:
            self._set_param(names.join(scope.ns, name), value, elem)

    def _param_value(self, scope: _Scope, el: etree._Element, source: str, kind: str, elem: Element) -> object:
        text = self._attr(scope, el, source) or ""
        if source == "value":
            return convert(text.strip(), kind)
        if source == "textfile":
            return convert(_read(Path(text)), kind)
        return Unknown(f"{source}: {text}", elem.file, elem.line)

    def _set_param(self, key: str, value: object, elem: Element) -> None:
        if isinstance(value, dict):
            for k, v in value.items():
                self._set_param(names.join(key, str(k)), v, elem)
        else:
            self.config.params[key] = (value, elem)

    def _tag_rosparam(self, path: Path, el: etree._Element, scope: _Scope, node_ns: str | None = None) -> None:
        command = self._attr(scope, el, "command") or "load"
        if command not in ("load", "dump", "delete"):
            raise LaunchError("command must be 'load', 'dump', or 'delete'")
        ns_attr, param = self._attr(scope, el, "ns") or "", self._attr(scope, el, "param") or ""
        joined = _ns_join(ns_attr, param)
        base = node_ns if node_ns is not None else scope.ns
        full = _ns_join(base, joined) if joined else base
        elem = self._element(path, el)
        file = self._attr(scope, el, "file")
        if file is not None and command == "delete":
            raise LaunchError("'file' attribute is invalid with 'delete' command")
        if command != "load":
            return
        text = _read(Path(file)) if file is not None else "".join(el.itertext())
        if _bool(self._attr(scope, el, "subst_value") or "false", "subst_value"):
            text = substitute(text, scope.subst)
        try:
            data = yaml.safe_load(text)
        except yaml.YAMLError as exc:
            raise LaunchError(f"invalid YAML: {exc}") from None
        data = {} if data is None else data
        if not joined and not isinstance(data, dict):
            raise LaunchError("'param' attribute must be set for non-dictionary values")
        if names.canonical(full) == "/" and not isinstance(data, dict):
            raise LaunchError("cannot load non-dictionary types into the global namespace '/'")
        self._set_param(names.canonical(full) or "/", data, elem)

    def _tag_node(self, path: Path, el: etree._Element, scope: _Scope, is_test: bool = False) -> None:
        for attr in el.keys():
            if attr not in NODE_ATTRS and not (is_test and attr in ("test-name", "time-limit", "retry")):
                self._diag(path, el, "launch-attr", f"unknown <{el.tag}> attribute '{attr}'", "warning")
        name = self._attr(scope, el, "name") if is_test else self._required(scope, el, "name")
        if is_test:
            name = name or self._required(scope, el, "test-name")
        if "/" in (name or ""):
            raise LaunchError("node name cannot contain a namespace")
        child = scope.child(self._ns_attr(scope, el))
        node_ns = names.join(child.ns, name or "")
        pkg, exe = self._required(scope, el, "pkg"), self._required(scope, el, "type")
        if not pkg or not exe:
            raise LaunchError("package and type must be non-empty")
        required = _bool(self._attr(scope, el, "required") or "false", "required")
        if required and _bool(self._attr(scope, el, "respawn") or "false", "respawn"):
            raise LaunchError("respawn and required cannot both be set to true")
        if (self._attr(scope, el, "output") or "log") not in ("log", "screen"):
            raise LaunchError("output must be one of 'log', 'screen'")
        if (self._attr(scope, el, "cwd") or "ROS_HOME").lower() not in ("ros_home", "node"):
            raise LaunchError("cwd must be one of 'ROS_HOME', 'node'")
        elem = self._element(path, el)
        for child_el in el:
            if not isinstance(child_el.tag, str) or self._enabled(scope, child_el) is not True:
                continue
            try:
                if child_el.tag == "remap":
                    self._tag_remap(path, child_el, child)
                elif child_el.tag == "param":
                    self._tag_param(path, child_el, child, node_ns)
                elif child_el.tag == "rosparam":
                    self._tag_rosparam(path, child_el, child, node_ns)
                elif child_el.tag != "env":
                    self._diag(path, child_el, "launch-tag", f"<{child_el.tag}> inside <{el.tag}> is ignored",
                               "warning")
            except (SubstitutionError, LaunchError) as exc:
                self._diag(path, child_el, "launch-invalid", f"<{child_el.tag}>: {exc}")
        for pname, value, pelem in scope.private:
            self._set_param(names.canonical(f"{node_ns}/{pname.lstrip('~')}"), value, pelem)
        self._add_node(path, el, LaunchNode(elem, pkg, exe, node_ns, child.ns, child.remaps, scope.condition,
                                            self._attr(scope, el, "args") or ""))

    def _tag_test(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        self._tag_node(path, el, scope, is_test=True)

    def _add_node(self, path: Path, el: etree._Element, node: LaunchNode) -> None:
        """Apply what a node does with its own command line: __name, __ns, remaps, _params;
        nodelet load/standalone become instances of the plugin type."""
        words = shlex.split(node.args) if node.args else []
        for word in words:
            if ":=" not in word:
                continue
            key, value = word.split(":=", 1)
            if key == "__name":
                node.name = names.join(node.namespace, value)
            elif key == "__ns":
                node.namespace = names.join("/", value)
                node.name = names.join(node.namespace, node.name.rsplit("/", 1)[-1])
            elif key.startswith("_") and not key.startswith("__"):
                self._set_param(names.join(node.name, key[1:]), auto_value(value), node.elem)
            elif not key.startswith("__"):
                node.remaps = [r for r in node.remaps if r[0] != key] + [(key, value, node.elem)]
        plain = [w for w in words if ":=" not in w]
        if node.pkg == "nodelet" and node.type == "nodelet" and plain[:1] in (["load"], ["standalone"]):
            node.plugin = plain[1] if len(plain) > 1 else None
            node.manager = plain[2] if plain[0] == "load" and len(plain) > 2 else None
        self.config.nodes.append(node)


def convert(text: str, kind: str) -> object:
    """roslaunch's typed parameter conversion."""
    if kind == "auto":
        return auto_value(text)
    if kind in ("str", "string"):
        return text
    if kind == "yaml":
        try:
            return yaml.safe_load(text)
        except yaml.YAMLError as exc:
            raise LaunchError(f"invalid YAML: {exc}") from None
    try:
        if kind == "int":
            return int(text)
        if kind == "double":
            return float(text)
    except ValueError:
        raise LaunchError(f"{text} is not a '{kind}' type") from None
    if kind in ("bool", "boolean"):
        return _bool(text, "value")
    raise LaunchError(f"unknown type '{kind}'")


def _bool(text: str, label: str) -> bool:
    value = text.lower().strip()
    if value in ("true", "1"):
        return True
    if value in ("false", "0"):
        return False
    raise LaunchError(f"invalid bool value for {label}: {text}")


def _ns_join(ns: str, name: str) -> str:
    """rosgraph's ns_join: global and private names stand alone, an empty ns adds nothing."""
    if name.startswith(("/", "~")) or not ns:
        return name
    return ns + name if ns.endswith("/") else f"{ns}/{name}"


def _read(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8")
    except OSError as exc:
        raise Unresolved(f"cannot read {path}: {exc.strerror}") from None
