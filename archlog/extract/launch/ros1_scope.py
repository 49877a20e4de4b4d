"""The core of the ROS 1 launch interpreter: roslaunch's scopes (LoaderContext), loading files
and element lists within the budget, conditions, attributes and diagnostics."""

from __future__ import annotations

import functools
import re
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, replace
from pathlib import Path

from lxml import etree

from archlog import budget, names, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.conditions import Guard, guard, settle
from archlog.extract.launch.load import ros2_by_name, ros2_launcher, ros2_marker
from archlog.extract.launch.model import (
    Element,
    LaunchConfig,
    LaunchError,
    LaunchNode,
    Nesting,
    RefusedRead,
    SubstitutionError,
    UnknownArg,
    Unresolved,
)
from archlog.extract.launch.read import boolean, open_xml
from archlog.extract.launch.ros1_subst import SubstContext, substitute
from archlog.extract.launch.ros2_execute import Ros2Launch
from archlog.extract.workspace.index import Workspace

_LEGAL_NAME = re.compile(r"[~/A-Za-z][\w/]*")


@dataclass
class _Scope:
    """roslaunch's LoaderContext: namespace, args, remaps and private params of one scope."""

    ns: str
    subst: SubstContext
    declared: list[str]
    remaps: list[tuple[str, str, Element]]
    private: list[tuple[str, object, Element]]
    condition: str | None = None
    guards: tuple[Guard | None, ...] = ()  # the undecided conditions' guards (conditions.py)
    pass_all_args: bool = False
    chain: tuple[Element, ...] = ()  # the <include> elements that led here, outermost first

    def child(self, ns: str | None) -> _Scope:
        """A group or node scope: args, declared names and remaps copied, the private-param list
        shared (a group copies it itself); the pass_all_args leniency is not inherited."""
        return replace(self, ns=child_ns(self.ns, ns), subst=self.subst.child(), declared=list(self.declared),
                       remaps=list(self.remaps), pass_all_args=False)

    def under(self, condition: str, one: Guard | None) -> _Scope:
        """This scope under one more undecided condition."""
        text = f"{self.condition} and {condition}" if self.condition else condition
        return replace(self, condition=text, guards=(*self.guards, one))

    def add_remap(self, src: str, dst: str, elem: Element) -> None:
        src, dst = names.canonical(src), names.canonical(dst)
        if not src or not dst:
            raise LaunchError("remap from/to attributes cannot be empty")
        for value in (src, dst):
            if not _LEGAL_NAME.fullmatch(value):
                raise LaunchError(f"remap name [{value}] is not a valid ROS name")
        self.remaps = [r for r in self.remaps if r[0] != src] + [(src, dst, elem)]


def child_ns(ns: str, sub: str | None) -> str:
    if not sub:
        return ns
    if sub.startswith("~"):
        raise LaunchError(f"cannot use the private name [{sub}] as a namespace")
    return names.join(ns, sub)


class Ros1Loader:
    """The core of the ROS 1 interpreter: files, element lists and their budget, conditions,
    attributes and diagnostics (the tags are handled by its subclasses)."""

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
        self._nesting = Nesting()  # element lists being loaded (a file, its groups, the files it includes)
        self._roots: dict[Path, tuple[etree._Element, bool]] = {}  # each file parsed (and its dialect told) once

    def load(self, files: list[Path], args: dict[str, str]) -> LaunchConfig:
        for path in files:
            subst = SubstContext(command_line_args(args), self.workspace.find, path)
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
        settle(self.config.nodes)
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

    def _diag(self, file: Path, el: etree._Element | None, code: str, message: str, severity: str = "error") -> None:
        line = el.sourceline if el is not None and el.sourceline else 1
        self.diagnostics.add(self.display(file), line, code, message, severity)

    def _hole(self, file: Path, el: etree._Element, code: str, message: str, severity: str = "error") -> None:
        """A diagnostic for a part of the configuration not read (an include or node skipped): the
        recovery summary counts it."""
        self._diag(file, el, code, message, severity)
        self.config.holes.append((self.display(file), el.sourceline or 1, message))

    @staticmethod
    def _attr(scope: _Scope, el: etree._Element, key: str) -> str | None:
        raw = el.get(key)
        return None if raw is None else substitute(raw, scope.subst)

    def _required(self, scope: _Scope, el: etree._Element, key: str) -> str:
        if el.get(key) is None:
            raise LaunchError(f"<{el.tag}> is missing the required attribute '{key}'")
        return self._attr(scope, el, key) or ""

    def _enabled(self, scope: _Scope, el: etree._Element) -> bool | tuple[str, Guard | None]:
        """True/False, or, when it cannot be resolved statically, the condition's text and guard."""
        if el.get("if") is not None and el.get("unless") is not None:
            raise LaunchError("cannot set both 'if' and 'unless' on the same tag")
        for key, want in (("if", True), ("unless", False)):
            raw = el.get(key)
            if raw is None:
                continue

            def decide(raw: str = raw, key: str = key, want: bool = want) -> bool:
                return parse_bool(substitute(raw, scope.subst), key) == want

            try:
                return decide()
            except Unresolved as exc:
                return f'{key}="{raw}" ({exc})', guard(raw, decide)
        return True

    # -- files and children ---------------------------------------------------------------
    def _file(self, path: Path, scope: _Scope) -> bool:
        """Load a file into the scope; False when it could not be read at all."""
        if ros2_by_name(path):
            return self._ros2_file(path, scope)
        if path not in self._roots:
            root = open_xml(path, self.display(path), self.diagnostics)
            if root is None:
                return False
            self._roots[path] = (root, ros2_marker(root) is not None)
        root, ros2 = self._roots[path]
        if ros2:
            return self._ros2_file(path, scope)
        self._children(path, root, scope)
        return True

    def _ros2_file(self, path: Path, scope: _Scope) -> bool:
        """A ROS 2 launch file (Python, XML or YAML), launched with this scope's args."""
        if self._ros2 is None:
            self._ros2 = ros2_launcher(self)
        return self._ros2.load(path, scope.subst.args, scope.subst.env, scope.chain)

    def _children(self, path: Path, parent: etree._Element, scope: _Scope) -> None:
        with self._nesting.deeper():
            for el in parent:
                if isinstance(el.tag, str):
                    self._child(path, el, scope)

    def _child(self, path: Path, el: etree._Element, scope: _Scope) -> None:
        """One element of a launch file or group, within the budget; each environment variable it
        read that the run was not given is noted at it."""
        with sandbox.reads_not_given() as unseen, self._crossing_at(path, el):
            budget.spend("elements")
            self._tag(path, el, scope)
        for read in unseen:
            self._diag(path, el, *sandbox.env_note(read), "note")

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
                self._conditional(path, el, enabled[0])
                scope = scope.under(*enabled)
            handler(path, el, scope)
        except (SubstitutionError, LaunchError) as exc:
            self._report(path, el, exc)

    def _report(self, path: Path, el: etree._Element, exc: SubstitutionError | LaunchError) -> None:
        """The diagnostic for an element roslaunch would reject (or that depends on this machine)."""
        if el.tag in ("param", "rosparam"):
            self.config.params_unknown.append((self._element(path, el), f"<{el.tag}> skipped: {exc}"))
        # a skipped <include> or <node> leaves nodes unseen: a hole in the recovery, not only a warning
        report = self._hole if el.tag in ("include", "node") else self._diag
        if isinstance(exc, RefusedRead):
            report(path, el, exc.code, f"<{el.tag}> skipped: {exc}", "warning")
        elif isinstance(exc, Unresolved):
            report(path, el, "launch-unresolved", f"<{el.tag}> skipped: {exc}; {_remedy(exc)}", "warning")
        else:
            self._diag(path, el, "launch-subst" if isinstance(exc, SubstitutionError) else "launch-invalid",
                       f"<{el.tag}>: {exc}")

    def _conditional(self, path: Path, el: etree._Element, condition: str) -> None:
        self._diag(path, el, "launch-condition",
                   f"condition {condition} cannot be resolved statically; <{el.tag}> kept as conditional", "note")


def parse_bool(text: str, label: str) -> bool:
    """A bool as if/unless and type="bool" read it: true/false/1/0, any case, stripped."""
    value = boolean(text.strip())
    if value is None:
        raise LaunchError(f"invalid bool value for {label}: {text}")
    return value


def bool_attr(text: str, label: str) -> bool:
    """A bool attribute (respawn, required, clear_params, pass_all_args, subst_value): true/false only."""
    value = boolean(text, numeric=False)
    if value is None:
        raise LaunchError(f"invalid bool value for {label}: {text!r}")
    return value


def command_line_args(args: dict[str, str]) -> dict[str, str | UnknownArg]:
    """Command-line args as roslaunch reads name:=value words: stripped, empty ones dropped, and
    `_name:=value` words left to the parameter server."""
    kept: dict[str, str | UnknownArg] = {}
    for key, value in args.items():
        key, value = key.strip(), value.strip()
        if key and value and ":=" not in value and not (len(key) > 1 and key[0] == "_" and key[1] != "_"):
            kept[key] = value
    return kept


def ns_join(ns: str, name: str) -> str:
    """rosgraph's ns_join: global and private names stand alone, an empty ns adds nothing."""
    if name.startswith(("/", "~")) or not ns:
        return name
    return ns + name if ns.endswith("/") else f"{ns}/{name}"



def _remedy(exc: Unresolved) -> str:
    """What can fix an unresolved value: the hint for its cause (a missing package is not fixed by
    --arg)."""
    text = str(exc)
    if package := re.match(r"package '([^']+)' not found", text):
        return (f"add the folder of package {package.group(1)} to the analysed paths (or give the nodes it "
                "starts models with --model)")
    if variable := re.match(r"environment variable (\S+) is not given", text):
        return f"pass it with --env {variable.group(1)}=VALUE"
    if arg := re.match(r"arg '([^']+)' is unknown", text):
        return f"pass it with --arg {arg.group(1)}:=VALUE"
    return "pass the value with --arg or --env"
