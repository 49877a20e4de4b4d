"""Interpret ROS 1 launch XML exactly as roslaunch 1.15 loads it (without running anything).

Scoping follows roslaunch's LoaderContext: a `<group>` copies the args and private params of
its parent, an `<include>` starts a fresh arg scope fed by its `<arg>` children (or by
pass_all_args), remaps apply to nodes declared after them in the same scope and below, and
`~param`s outside a node apply to every node declared after them in that scope. Where roslaunch
would stop with an error, archlog reports a diagnostic at the element and goes on.

Each launch file given is one unit of the expansion budget (archlog.budget): every element
(after includes) and nesting level counts, and an include of a file that is being loaded (a
cycle) is refused as roslaunch would fail. A limit crossed is a `budget-exceeded` diagnostic at
the innermost element that crossed it: a count spent past its limit ends the unit there (what
was read stays), a nesting or a string refused before it was built skips only that element.
"""

from __future__ import annotations

import functools
import math
import os
import re
import shlex
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

import yaml
from lxml import etree

from archlog import budget, names, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract import bounded_yaml
from archlog.extract.files import parse_xml, unreadable
from archlog.extract.substitution import (RefusedRead, SubstContext, SubstitutionError, UnknownArg, Unresolved,
                                          arithmetic, auto_value, read_file, substitute, unresolved_code)
from archlog.extract.workspace import Workspace
from archlog.values import Unknown

if TYPE_CHECKING:
    from archlog.extract.launch2 import Ros2Launch

NODE_ATTRS = {"pkg", "type", "machine", "name", "args", "output", "respawn", "respawn_delay", "cwd", "ns",
              "clear_params", "launch-prefix", "required", "if", "unless"}
TEST_ONLY_ATTRS = {"test-name", "time-limit", "retry"}
NOT_FOR_TESTS = ("respawn", "respawn_delay", "output")
_LEGAL_NAME = re.compile(r"[~/A-Za-z][\w/]*")


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
    declared: str = ""  # the name as declared (before __name/__ns in args); roslaunch checks these
    chain: tuple[Element, ...] = ()  # the <include> elements it was loaded through, outermost first
    # ROS 2: parameters as (node-name pattern, dotted name, value, element); the pattern is "" for
    # parameters given to this node directly, else a parameter file's node key ("/**", "/ns/talker")
    parameters: list[tuple[str, str, object, Element]] = field(default_factory=list)
    ros2: bool = False  # remaps then apply first-match-wins, as rcl does (roslaunch's last one wins)

    @property
    def kind(self) -> tuple[str, str]:
        """What runs: (package, executable), (package, Type) of a nodelet plugin pkg/Type, or
        (package, ns::Class) of a ROS 2 component."""
        if self.plugin and "::" in self.plugin:
            return self.pkg, self.plugin
        if self.plugin and "/" in self.plugin:
            pkg, plugin = self.plugin.split("/", 1)
            return pkg, plugin
        return self.pkg, self.type


@dataclass
class LaunchConfig:
    """The system configuration: node instances, parameter values, and every scope-level remap
    (resolved in its scope's namespace) so that one that reaches no node can be reported."""

    nodes: list[LaunchNode] = field(default_factory=list)
    params: dict[str, tuple[object, Element]] = field(default_factory=dict)
    scope_remaps: list[tuple[Element, str, str]] = field(default_factory=list)


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
    chain: tuple[Element, ...] = ()  # the <include> elements that led here, outermost first

    def child(self, ns: str | None) -> "_Scope":
        """A group or node scope: args, declared names and remaps copied, the private-param list
        shared (a group copies it itself); the pass_all_args leniency is not inherited."""
        return replace(self, ns=_child_ns(self.ns, ns), subst=self.subst.child(), declared=list(self.declared),
                       remaps=list(self.remaps), pass_all_args=False)

    def add_remap(self, src: str, dst: str, elem: Element) -> None:
        src, dst = names.canonical(src), names.canonical(dst)
        if not src or not dst:
            raise LaunchError("remap from/to attributes cannot be empty")
        for value in (src, dst):
            if not _LEGAL_NAME.fullmatch(value):
                raise LaunchError(f"remap name [{value}] is not a valid ROS name")
        self.remaps = [r for r in self.remaps if r[0] != src] + [(src, dst, elem)]


def _child_ns(ns: str, sub: str | None) -> str:
    if not sub:
        return ns
    if sub.startswith("~"):
        raise LaunchError(f"cannot use the private name [{sub}] as a namespace")
    return names.join(ns, sub)


class LaunchInterpreter:
    """Loads one or more launch files into a single LaunchConfig, reporting problems as diagnostics."""

    def __init__(self, workspace: Workspace, diagnostics: DiagnosticSink) -> None:
        self.workspace = workspace
        self.display = functools.cache(workspace.display)  # paths as reports show them (resolving is slow)
        self.diagnostics = diagnostics
        self.config = LaunchConfig()
        self._count = 0
        self._machines: dict[str, tuple[object, ...]] = {}
        self._machine_uses: list[tuple[str, Path, etree._Element]] = []
        self._declared: list[tuple[str, Path, etree._Element, LaunchNode]] = []
        self._rosparam_yaml = False  # roslaunch imports rosparam (and its YAML angles) at the first load
        self._ros2: Ros2Launch | None = None
        self._nesting = 0  # element lists being loaded (a file, its groups, the files it includes)

    def load(self, files: list[Path], args: dict[str, str]) -> LaunchConfig:
        for path in files:
            subst = SubstContext(_command_line(args), self.workspace.find, path)
            root = args["__ns"] if "__ns" in args else subst.env.get("ROS_NAMESPACE", "/")
            with budget.scope():
                try:
                    self._file(path, _Scope(names.join("/", root), subst, [], [], []))
                except budget.Crossed as crossing:
                    self.report_crossing(crossing)
        for machine, path, el in self._machine_uses:
            if machine not in self._machines:
                self._diag(path, el, "launch-invalid", f"<{el.tag}>: unknown machine [{machine}]")
        self._check_declared_names()
        return self.config

    def _check_declared_names(self) -> None:
        """roslaunch rejects two <node>s declared with one name. When they keep that name, the
        duplicate-node rule reports it; here only those that args rename apart."""
        first: dict[str, LaunchNode] = {}
        for declared, path, el, node in self._declared:
            other = first.setdefault(declared, node)
            if other is not node and other.name != node.name:
                self._diag(path, el, "launch-invalid",
                           f"<node>: roslaunch rejects a second node declared as [{declared}], even though "
                           f"its args rename it to [{node.name}]")

    # -- helpers --------------------------------------------------------------------------
    def _element(self, file: Path, el: etree._Element) -> Element:
        return self.element_at(file, el.sourceline or 1)

    def element_at(self, file: Path, line: int) -> Element:
        """A new element at file:line (ids are shared by both launch dialects)."""
        self._count += 1
        return Element(f"e{self._count:05d}", self.display(file), line)

    def include_cycle(self, target: Path, file: Path, chain: tuple[Element, ...]) -> str | None:
        """When `target` is being loaded already (by `file` or the includes of `chain` that led to
        it), the files of the cycle an include of it would close, else None."""
        opened = [e.file for e in chain] + [self.display(file)]
        shown = self.display(target)
        return " -> ".join([*opened[opened.index(shown):], shown]) if shown in opened else None

    def _diag(self, file: Path, el: etree._Element | None, code: str, message: str, severity: str = "error") -> None:
        line = el.sourceline if el is not None and el.sourceline else 1
        self.diagnostics.add(self.display(file), line, code, message, severity)

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
        shown = self.display(path)
        if path.suffix in (".py", ".yaml", ".yml"):
            return self._ros2_file(path, scope)
        try:
            root = parse_xml(path, "launch", remove_comments=True)
        except etree.XMLSyntaxError as exc:
            self.diagnostics.add(shown, exc.lineno or 1, "launch-xml", f"malformed launch XML: {exc.msg}", "error")
            return False
        except sandbox.Refused as exc:
            self.diagnostics.add(shown, 1, exc.code, f"cannot read launch file: {exc}", "error")
            return False
        if root.tag != "launch":
            self._diag(path, root, "launch-xml", f"root element is <{root.tag}>, not <launch>")
            return False
        if ros2_marker(root) is not None:
            return self._ros2_file(path, scope)
        self._children(path, root, scope)
        return True

    def _ros2_file(self, path: Path, scope: _Scope) -> bool:
        """A ROS 2 launch file (Python, XML or YAML), launched with this scope's args."""
        if self._ros2 is None:
            from archlog.extract import launch2_frontend, launch2_python  # they build on this module
            from archlog.extract.launch2 import PYTHON, XML, YAML, Ros2Launch
            self._ros2 = Ros2Launch(self, {PYTHON: launch2_python.describe, XML: launch2_frontend.describe_xml,
                                           YAML: launch2_frontend.describe_yaml})
        return self._ros2.load(path, scope.subst.args, scope.subst.env, scope.chain)

    def _children(self, path: Path, parent: etree._Element, scope: _Scope) -> None:
        budget.current().check("depth", self._nesting + 1)
        self._nesting += 1
        try:
            for el in parent:
                if isinstance(el.tag, str):
                    self._child(path, el, scope)
        finally:
            self._nesting -= 1

    def _child(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        """One element of a launch file or group, within the budget; each environment variable it
        read that the run was not given is noted at it."""
        with sandbox.reads_not_given() as unseen:
            with self._crossing_at(path, el):
                budget.spend("elements")
                self._tag(path, el, scope)
        for name in unseen:
            self._diag(path, el, "env-not-given", sandbox.not_given_message(name), "note")

    @contextmanager
    def _crossing_at(self, path: Path, el: etree._Element) -> Iterator[None]:
        """A limit crossed inside `el` (and not deeper) is crossed at `el`; a crossing that does not
        end the unit is reported and `el` skipped."""
        try:
            yield
            return
        except (budget.BudgetExceeded, RecursionError, MemoryError) as exc:
            crossing = budget.crossed(self.display(path), el.sourceline or 1, exc)
        except budget.Crossed as exc:
            crossing = exc
        if crossing.final:
            raise crossing
        self.report_crossing(crossing)

    def report_crossing(self, crossing: budget.Crossed) -> None:
        """The `budget-exceeded` diagnostic of a crossing."""
        after = "the rest of this launch configuration is not read" if crossing.final else "skipped"
        self.diagnostics.add(crossing.file, crossing.line, "budget-exceeded", f"{crossing.exceeded}; {after}", "error")

    def _tag(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        handler = getattr(self, f"_tag_{el.tag}", None)
        if handler is None:
            if el.tag != "master":
                self._diag(path, el, "launch-tag", f"unrecognized tag <{el.tag}> ignored", "warning")
            return
        try:
            enabled = self._enabled(scope, el)
            if enabled is False:
                return
            if enabled is not True:
                self._conditional(path, el, enabled)
            handler(path, el, scope if enabled is True else replace(scope, condition=enabled))
        except (SubstitutionError, LaunchError) as exc:
            self._report(path, el, exc)

    def _report(self, path: Path, el: etree._Element, exc: SubstitutionError | LaunchError) -> None:
        """The diagnostic for an element roslaunch would reject (or that depends on this machine)."""
        if isinstance(exc, RefusedRead):
            self._diag(path, el, exc.code, f"<{el.tag}> skipped: {exc}", "warning")
        elif isinstance(exc, Unresolved):
            self._diag(path, el, "launch-unresolved",
                       f"<{el.tag}> skipped: {exc}; pass the value with --arg or --env",
                       "warning")
        else:
            self._diag(path, el, "launch-subst" if isinstance(exc, SubstitutionError) else "launch-invalid",
                       f"<{el.tag}>: {exc}")

    def _conditional(self, path: Path, el: etree._Element, condition: str) -> None:
        self._diag(path, el, "launch-condition",
                   f"condition {condition} cannot be resolved statically; <{el.tag}> kept as conditional", "note")

    def _tag_arg(self, path: Path, el: etree._Element, scope: _Scope,
                 target: dict[str, str | UnknownArg] | None = None) -> str:
        """Declare an arg; values resolve in `scope` and are stored in `target` (an include's
        passed args) or in the scope's own args. roslaunch substitutes value, default and doc
        even when they end up unused."""
        name = self._required(scope, el, "name")
        values: dict[str, str | UnknownArg] = {}
        for key in ("value", "default", "doc"):
            if el.get(key) is None:
                continue
            try:
                values[key] = self._attr(scope, el, key) or ""
            except Unresolved as exc:
                values[key] = UnknownArg(str(exc))
        if "value" in values and "default" in values:
            raise LaunchError("<arg> must have only one of value/default")
        if name in scope.declared and not scope.pass_all_args:
            raise LaunchError(f"arg '{name}' has already been declared")
        if name not in scope.declared:
            scope.declared.append(name)
        args = scope.subst.args if target is None else target
        if "value" in values and name in args and not scope.pass_all_args:
            raise LaunchError(f"cannot override arg '{name}', which has already been set")
        if "value" in values or ("default" in values and name not in args):
            value = values.get("value", values.get("default", ""))
            args[name] = value
            if isinstance(value, UnknownArg):
                self._diag(path, el, "launch-arg-unknown", f"arg '{name}' is not known statically: {value.reason}",
                           "note")
        return name

    def _tag_group(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        child = scope.child(self._ns_attr(scope, el))
        child.private = list(scope.private)
        self._clear_params(scope, el, is_node=False)
        self._children(path, el, child)

    def _ns_attr(self, scope: _Scope, el: etree._Element) -> str | None:
        ns = self._attr(scope, el, "ns")
        if ns is not None and not ns:
            raise LaunchError(f"<{el.tag}> has an empty 'ns' attribute")
        return ns

    def _clear_params(self, scope: _Scope, el: etree._Element, is_node: bool) -> None:
        """clear_params only clears at launch time; here it is just checked."""
        value = self._attr(scope, el, "clear_params")
        if value and _bool_attr(value, "clear_params") and not is_node and el.get("ns") is None:
            raise LaunchError("'ns' attribute must be set in order to use 'clear_params'")

    def _tag_env(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        """<env> only changes the environment of the processes started; it is checked."""
        if not self._required(scope, el, "name"):
            raise LaunchError("'name' attribute must be non-empty")
        self._required(scope, el, "value")

    def _tag_machine(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        """Record a machine, checked as roslaunch checks it (nodes may name it, even before)."""
        if any(el.get(key) is not None and self._attr(scope, el, key)
               for key in ("ros-root", "ros-package-path", "ros-ip", "ros-hostname")):
            raise LaunchError("ros-* attributes are not supported since ROS Fuerte")
        name, address = self._required(scope, el, "name"), self._required(scope, el, "address")
        loader, port, user, password, default, timeout = (
            self._attr(scope, el, key) for key in ("env-loader", "ssh-port", "user", "password", "default", "timeout"))
        try:
            ssh_port = int(port or "22")
        except ValueError:
            raise LaunchError(f"invalid ssh-port: {port}") from None
        default = (default or "false").lower()
        if default not in ("true", "false", "never"):
            raise LaunchError(f"invalid value for 'default': {default}")
        if timeout is not None:
            try:
                seconds = float(timeout)
            except ValueError:
                raise LaunchError(f"'timeout' must be a number: [{timeout}]") from None
            if seconds <= 0:
                raise LaunchError(f"'timeout' must be a positive number: [{timeout}]")
        for child in el:
            if isinstance(child.tag, str) and child.tag == "env":
                raise LaunchError("<env> inside <machine> is not supported since ROS Fuerte")
        key = (address, loader, ssh_port, user or "", password or "", timeout and float(timeout), default != "never")
        if self._machines.setdefault(name, key) != key:
            raise LaunchError(f"machine [{name}] already added and does not match the duplicate entry")

    def _tag_remap(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        src, dst, elem = self._required(scope, el, "from"), self._required(scope, el, "to"), self._element(path, el)
        scope.add_remap(src, dst, elem)
        self.config.scope_remaps.append((elem, names.join(scope.ns, src), names.join(scope.ns, dst)))

    def _tag_include(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        target = Path(self._required(scope, el, "file"))
        pass_all = _bool_attr(self._attr(scope, el, "pass_all_args") or "false", "pass_all_args")
        ns = _child_ns(scope.ns, self._ns_attr(scope, el))
        self._clear_params(scope, el, is_node=False)
        passed: dict[str, str | UnknownArg] = dict(scope.subst.args) if pass_all else {}
        declared: list[str] = list(passed)
        arg_scope = replace(scope, subst=scope.subst.child(), declared=declared, pass_all_args=pass_all)
        arg_elements: dict[str, etree._Element] = {}
        for child in el:
            if not isinstance(child.tag, str):
                continue
            tag = child.tag.lower()
            if tag not in ("arg", "env"):
                self._diag(path, child, "launch-tag", f"<{child.tag}> inside <include> is ignored by roslaunch",
                           "warning")
                continue
            try:
                if self._enabled(arg_scope, child) is not True:
                    continue
                with self._crossing_at(path, child):
                    if tag == "env":
                        self._tag_env(path, child, arg_scope)
                    else:
                        arg_elements[self._tag_arg(path, child, arg_scope, passed)] = child
            except (SubstitutionError, LaunchError) as exc:
                self._report(path, child, exc)
                return
        missing = [a for a in declared if a not in passed]
        for name in missing:
            self._diag(path, arg_elements.get(name, el), "launch-invalid",
                       f"<include>: arg '{name}' is passed without a value or default")
        if missing:
            return
        if (refused := unreadable(target, "launch")) is not None:
            missing = refused.code == "missing"
            self._diag(path, el, "launch-include" if missing else refused.code,
                       f"included file not found: {target}" if missing else f"<include> skipped: {refused}")
            return
        cycle = self.include_cycle(target, path, scope.chain)
        if cycle is not None:
            self._diag(path, el, "launch-include-cycle", f"<include>: {target.name} is being loaded already "
                       f"({cycle}); roslaunch would fail")
            return
        # roslaunch hands the ~param list on to the included file, unless it is still empty
        private = scope.private if scope.private else []
        child_scope = _Scope(ns, scope.subst.child(args=passed, file=target), [], list(scope.remaps), private,
                             scope.condition, pass_all, (*scope.chain, self._element(path, el)))
        if self._file(target, child_scope) and not pass_all:
            for name in passed:
                if name not in child_scope.declared:
                    self._diag(path, arg_elements.get(name, el), "launch-invalid",
                               f"<include>: unused arg '{name}': {target.name} does not declare it")

    def _tag_param(self, path: Path, el: etree._Element, scope: _Scope,
                   local: list[tuple[str, object, Element]] | None = None) -> None:
        """A parameter; `~name`s (and every <param> of a node, given `local`) wait for the nodes."""
        if el.get("name") is None:
            raise LaunchError("<param> is missing the required attribute 'name'")
        name = substitute(el.get("name", "").strip(), scope.subst)
        elem = self._element(path, el)
        sources = [k for k in ("value", "textfile", "binfile", "command") if el.get(k) is not None]
        if len(sources) != 1:
            raise LaunchError("<param> must have one and only one of value/textfile/binfile/command")
        kind = (el.get("type") or "auto").lower().strip()
        try:
            value = self._param_value(scope, el, sources[0], kind, elem)
        except Unresolved as exc:
            value = Unknown(f"{el.get(sources[0])} ({exc})", elem.file, elem.line)
            self._diag(path, el, unresolved_code(exc, "launch-unresolved"),
                       f"<param> value not known statically: {exc}", "warning")
        if local is not None:
            local.append((name, value, elem))
        elif name.startswith("~"):
            scope.private.append((name, value, elem))
        else:
            self._put(names.join(scope.ns, name), value, elem)

    def _param_value(self, scope: _Scope, el: etree._Element, source: str, kind: str, elem: Element) -> object:
        if source == "command":  # never run: its words are kept, and xacro need not be installed to read them
            find = scope.subst.find
            subst = replace(scope.subst, find=lambda pkg: find(pkg) or (Path(pkg) if pkg == "xacro" else None))
            return Unknown(f"command: {substitute(el.get(source) or '', subst)}", elem.file, elem.line)
        text = self._attr(scope, el, source) or ""
        if source == "value":
            return convert(text.strip(), kind, self._rosparam_yaml)
        if source == "textfile":
            return convert(read_file(text, "description"), kind, self._rosparam_yaml)
        return Unknown(f"{source}: {text}", elem.file, elem.line)

    def _put(self, key: str, value: object, elem: Element) -> None:
        """One parameter (a dict value stays one parameter, as for <param type="yaml">)."""
        self.config.params[names.canonical(key)] = (value, elem)

    def _put_tree(self, key: str, value: object, elem: Element) -> None:
        """rosparam's loading: a dict becomes one parameter per leaf."""
        if not isinstance(value, dict):
            self._put(key, value, elem)
            return
        for k, v in value.items():
            if not isinstance(k, str):
                raise LaunchError(f"parameter key {k!r} is not a string")
            self._put_tree(_ns_join(key, k), v, elem)

    def _put_private(self, node_ns: str, name: str, value: object, elem: Element) -> None:
        self._put(f"{node_ns}/{name[1:] if name.startswith('~') else name}", value, elem)

    def _tag_rosparam(self, path: Path, el: etree._Element, scope: _Scope, node_ns: str | None = None) -> None:
        command = self._attr(scope, el, "command") or "load"
        ns_attr, param = self._attr(scope, el, "ns") or "", self._attr(scope, el, "param") or ""
        file = self._attr(scope, el, "file")
        subst = _bool_attr(self._attr(scope, el, "subst_value") or "false", "subst_value")
        if command not in ("load", "dump", "delete"):
            raise LaunchError("command must be 'load', 'dump', or 'delete'")
        joined = _ns_join(ns_attr, param)
        base = node_ns if node_ns is not None else scope.ns
        full = _ns_join(base, joined) if joined else base
        elem = self._element(path, el)
        if file is not None and command == "load" and sandbox.current().inside(file) and not os.path.lexists(file):
            raise Unresolved(f"file does not exist [{file}]")
        if file is not None and command == "delete":
            raise LaunchError("'file' attribute is invalid with 'delete' command")
        if command != "load":
            return
        text = read_file(file, "params") if file is not None else "".join(
            [el.text or ""] + [child.tail or "" for child in el])
        if subst:
            text = substitute(text, scope.subst)
        self._rosparam_yaml = True
        data = _yaml(text, True)
        data = {} if data is None else data
        if not joined and not isinstance(data, dict):
            raise LaunchError("'param' attribute must be set for non-dictionary values")
        if full == "/" and not isinstance(data, dict):
            raise LaunchError("cannot load non-dictionary types into the global namespace '/'")
        self._put_tree(full, data, elem)

    def _tag_node(self, path: Path, el: etree._Element, scope: _Scope, is_test: bool = False) -> None:
        for attr in el.keys():
            if attr not in NODE_ATTRS and not (is_test and attr in TEST_ONLY_ATTRS):
                self._diag(path, el, "launch-attr", f"unknown <{el.tag}> attribute '{attr}'", "warning")
        name = self._attr(scope, el, "name") if is_test else self._required(scope, el, "name")
        if is_test:
            self._test_attrs(scope, el)
            name = name or self._attr(scope, el, "test-name")
        child = scope.child(self._ns_attr(scope, el))
        self._clear_params(scope, el, is_node=True)
        node_ns = names.join(child.ns, name or "")
        pkg, exe = self._required(scope, el, "pkg"), self._required(scope, el, "type")
        machine, output, respawn, delay, cwd, required = (
            self._attr(scope, el, key) for key in ("machine", "output", "respawn", "respawn_delay", "cwd", "required"))
        if _bool_attr(required or "false", "required") and _bool_attr(respawn or "false", "respawn"):
            raise LaunchError("respawn and required cannot both be set to true")
        if delay is not None:
            try:
                float(delay)
            except ValueError:
                raise LaunchError(f"invalid float value for respawn_delay: {delay}") from None
        if "/" in (name or ""):
            raise LaunchError("node name cannot contain a namespace")
        if not pkg.strip() or not exe.strip():
            raise LaunchError("package and type must be non-empty")
        if output is not None and output not in ("log", "screen"):
            raise LaunchError("output must be one of 'log', 'screen'")
        if cwd is not None and cwd not in ("ROS_HOME", "ros_home", "node"):
            raise LaunchError("cwd must be one of 'ROS_HOME', 'node'")
        elem = self._element(path, el)
        local: list[tuple[str, object, Element]] = []
        for child_el in el:
            if isinstance(child_el.tag, str):
                with self._crossing_at(path, child_el):
                    self._node_child(path, child_el, scope, child, node_ns, local)
        # the scope's ~params first, then the node's own <param>s (its <rosparam>s are already set)
        for pname, value, pelem in scope.private + local:
            self._put_private(node_ns, pname, value, pelem)
        if machine:
            self._machine_uses.append((machine, path, el))
        node = LaunchNode(elem, pkg, exe, node_ns, child.ns, child.remaps, scope.condition,
                          self._attr(scope, el, "args") or "", declared="" if is_test else node_ns,
                          chain=scope.chain)
        if not is_test:
            self._declared.append((node_ns, path, el, node))
        self._add_node(path, el, node)

    def _node_child(self, path: Path, el: etree._Element, scope: _Scope, child: _Scope, node_ns: str,
                    local: list[tuple[str, object, Element]]) -> None:
        """A tag inside <node>/<test>: remaps resolve in the enclosing scope, the rest in the node's."""
        tag = el.tag.lower()
        try:
            if self._enabled(child, el) is not True:
                return
            if tag == "remap":
                child.add_remap(self._required(scope, el, "from"), self._required(scope, el, "to"),
                                self._element(path, el))
            elif tag == "param":
                self._tag_param(path, el, child, local)
            elif tag == "rosparam":
                self._tag_rosparam(path, el, child, node_ns)
            elif tag == "env":
                self._tag_env(path, el, child)
            else:
                self._diag(path, el, "launch-tag", f"<{el.tag}> inside <node> is ignored", "warning")
        except (SubstitutionError, LaunchError) as exc:
            self._report(path, el, exc)

    def _test_attrs(self, scope: _Scope, el: etree._Element) -> None:
        for attr in NOT_FOR_TESTS:
            if el.get(attr) is not None:
                raise LaunchError(f"<test> tags cannot have '{attr}' attribute")
        self._required(scope, el, "test-name")
        limit, retry = self._attr(scope, el, "time-limit"), self._attr(scope, el, "retry")
        if limit:
            try:
                seconds = float(limit)
            except ValueError:
                raise LaunchError(f"'time-limit' must be a number: [{limit}]") from None
            if seconds <= 0:
                raise LaunchError("'time-limit' must be a positive number")
        if retry:
            try:
                int(retry)
            except ValueError:
                raise LaunchError(f"'retry' must be a number: [{retry}]") from None

    def _tag_test(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        self._tag_node(path, el, scope, is_test=True)

    def _add_node(self, path: Path, el: etree._Element, node: LaunchNode) -> None:
        """Apply what a node does with its own command line: __name, __ns, remaps, _params;
        nodelet load/standalone become instances of the plugin type."""
        try:
            words = shlex.split(node.args) if node.args else []
        except ValueError as exc:  # roslaunch fails the same way
            raise LaunchError(f"args cannot be split into words ({exc}): [{node.args}]") from None
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
                self._put(names.join(node.name, key[1:]), auto_value(value), node.elem)
            elif not key.startswith("__"):
                node.remaps = [r for r in node.remaps if r[0] != key] + [(key, value, node.elem)]
        plain = [w for w in words if ":=" not in w]
        if node.pkg == "nodelet" and node.type == "nodelet" and plain[:1] in (["load"], ["standalone"]):
            node.plugin = plain[1] if len(plain) > 1 else None
            node.manager = plain[2] if plain[0] == "load" and len(plain) > 2 else None
        self.config.nodes.append(node)


_ROS2_TAGS = {"let", "push-ros-namespace", "push_ros_namespace", "set_remap", "set_parameter", "set_env",
              "executable", "node_container", "composable_node", "load_composable_node", "pop-ros-namespace"}
_ROS2_SUBST = ("$(var ", "$(find-pkg-share ", "$(find-pkg-prefix ", "$(find-exec ", "$(exec-in-pkg ")


def ros2_marker(root: etree._Element) -> etree._Element | None:
    """The first element that shows a <launch> file is ROS 2's dialect (both use .launch.xml):
    a ROS 2-only tag, a node with `exec`, or a ROS 2 substitution in an attribute."""
    for el in root.iter():
        if not isinstance(el.tag, str):
            continue
        if el.tag in _ROS2_TAGS or (el.tag == "node" and el.get("exec") is not None) or \
                any(v.find(marker) >= 0 for v in el.attrib.values() for marker in _ROS2_SUBST):
            return el
    return None


def convert(text: str, kind: str, angles: bool = False) -> object:
    """roslaunch's typed parameter conversion (`angles`: YAML knows rosparam's rad()/deg())."""
    if kind == "auto":
        return auto_value(text)
    if kind in ("str", "string"):
        return text
    if kind == "yaml":
        return _yaml(text, angles)
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
    """A bool as if/unless and type="bool" read it: true/false/1/0, any case, stripped."""
    value = text.lower().strip()
    if value in ("true", "1"):
        return True
    if value in ("false", "0"):
        return False
    raise LaunchError(f"invalid bool value for {label}: {text}")


def _bool_attr(text: str, label: str) -> bool:
    """A bool attribute (respawn, required, clear_params, pass_all_args, subst_value): true/false only."""
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    raise LaunchError(f"invalid bool value for {label}: {text!r}")


def _command_line(args: dict[str, str]) -> dict[str, str]:
    """Command-line args as roslaunch reads name:=value words: stripped, empty ones dropped, and
    `_name:=value` words left to the parameter server."""
    kept = {}
    for key, value in args.items():
        key, value = key.strip(), value.strip()
        if key and value and ":=" not in value and not (len(key) > 1 and key[0] == "_" and key[1] != "_"):
            kept[key] = value
    return kept


class _RosparamLoader(bounded_yaml.BoundedLoader):
    """PyYAML's safe loader plus the angle forms rosparam registers: rad(...), deg(...), !radians, !degrees."""


def _radians(loader: yaml.SafeLoader, node: yaml.Node) -> float:
    text = str(loader.construct_scalar(node)).strip()  # type: ignore[arg-type]
    text = text[4:-1] if text.startswith("rad(") else text
    try:
        return float(arithmetic(text))  # type: ignore[arg-type]
    except (SubstitutionError, TypeError, ValueError, ArithmeticError) as exc:
        raise LaunchError(f"invalid radian expression: {text} ({exc})") from None


def _degrees(loader: yaml.SafeLoader, node: yaml.Node) -> float:
    text = str(loader.construct_scalar(node))  # type: ignore[arg-type]
    text = text.strip()[4:-1] if text.startswith("deg(") else text
    try:
        return float(text) * math.pi / 180.0
    except ValueError:
        raise LaunchError(f"invalid degree value: {text}") from None


_RosparamLoader.add_constructor("!radians", _radians)
_RosparamLoader.add_constructor("!degrees", _degrees)
_RosparamLoader.add_implicit_resolver("!degrees", re.compile(r"^deg\([^\)]*\)$"), list("deg("))
_RosparamLoader.add_implicit_resolver("!radians", re.compile(r"^rad\([^\)]*\)$"), list("rad("))


def _yaml(text: str, angles: bool) -> object:
    try:
        return bounded_yaml.load(text, _RosparamLoader if angles else bounded_yaml.BoundedLoader)
    except yaml.YAMLError as exc:
        raise LaunchError(f"invalid YAML: {exc}") from None


def _ns_join(ns: str, name: str) -> str:
    """rosgraph's ns_join: global and private names stand alone, an empty ns adds nothing."""
    if name.startswith(("/", "~")) or not ns:
        return name
    return ns + name if ns.endswith("/") else f"{ns}/{name}"

