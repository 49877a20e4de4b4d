"""roslaunch's arguments and parameters: <arg>, <param> and <rosparam>, typed conversion, and
the YAML angles (rad(), deg()) rosparam adds."""

from __future__ import annotations

import math
import os
import re
from dataclasses import replace
from pathlib import Path

import yaml
from lxml import etree

from archlog import names, sandbox
from archlog.extract.launch import bounded_yaml
from archlog.extract.launch.evaluate import arithmetic
from archlog.extract.launch.model import (
    Element,
    LaunchError,
    SubstitutionError,
    UnknownArg,
    Unresolved,
    read_file,
    unresolved_code,
)
from archlog.extract.launch.ros1_scope import Ros1Loader, _Scope, bool_attr, ns_join, parse_bool
from archlog.extract.launch.ros1_subst import auto_value, substitute
from archlog.values import Unknown


class Ros1Params(Ros1Loader):
    """The ROS 1 interpreter's <arg>, <param> and <rosparam> tags and the parameters they set."""

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
            self._put_tree(ns_join(key, k), v, elem)

    def _put_private(self, node_ns: str, name: str, value: object, elem: Element) -> None:
        self._put(f"{node_ns}/{name[1:] if name.startswith('~') else name}", value, elem)

    def _tag_rosparam(self, path: Path, el: etree._Element, scope: _Scope, node_ns: str | None = None) -> None:
        command = self._attr(scope, el, "command") or "load"
        ns_attr, param = self._attr(scope, el, "ns") or "", self._attr(scope, el, "param") or ""
        file = self._attr(scope, el, "file")
        subst = bool_attr(self._attr(scope, el, "subst_value") or "false", "subst_value")
        if command not in ("load", "dump", "delete"):
            raise LaunchError("command must be 'load', 'dump', or 'delete'")
        joined = ns_join(ns_attr, param)
        base = node_ns if node_ns is not None else scope.ns
        full = ns_join(base, joined) if joined else base
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
        return parse_bool(text, "value")
    raise LaunchError(f"unknown type '{kind}'")


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

