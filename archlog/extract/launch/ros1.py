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

import shlex
from dataclasses import replace
from pathlib import Path

from lxml import etree

from archlog import budget, names
from archlog.extract.files import unreadable
from archlog.extract.launch.model import Element, LaunchError, LaunchNode, SubstitutionError, UnknownArg, include_cycle
from archlog.extract.launch.ros1_params import Ros1Params
from archlog.extract.launch.ros1_scope import _Scope, bool_attr, child_ns
from archlog.extract.launch.ros1_subst import auto_value

NODE_ATTRS = {"pkg", "type", "machine", "name", "args", "output", "respawn", "respawn_delay", "cwd", "ns",
              "clear_params", "launch-prefix", "required", "if", "unless"}
TEST_ONLY_ATTRS = {"test-name", "time-limit", "retry"}
NOT_FOR_TESTS = ("respawn", "respawn_delay", "output")


class LaunchInterpreter(Ros1Params):
    """Loads one or more launch files into a single LaunchConfig, reporting problems as diagnostics:
    the tags that make groups, includes, machines, remaps and nodes."""

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
        if value and bool_attr(value, "clear_params") and not is_node and el.get("ns") is None:
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
        pass_all = bool_attr(self._attr(scope, el, "pass_all_args") or "false", "pass_all_args")
        ns = child_ns(scope.ns, self._ns_attr(scope, el))
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
            absent = refused.code == "missing"
            self._hole(path, el, "launch-include" if absent else refused.code,
                       f"included file not found: {target}" if absent else f"<include> skipped: {refused}")
            return
        cycle = include_cycle(self.display, target, path, scope.chain)
        if cycle is not None:
            self._hole(path, el, "launch-include-cycle", f"<include>: {target.name} is being loaded already "
                       f"({cycle}); roslaunch would fail")
            return
        # roslaunch hands the ~param list on to the included file, unless it is still empty
        private = scope.private if scope.private else []
        child_scope = _Scope(ns, scope.subst.child(args=passed, file=target), [], list(scope.remaps), private,
                             scope.condition, scope.guards, pass_all, (*scope.chain, self._element(path, el)))
        if self._file(target, child_scope) and not pass_all:
            for name in passed:
                if name not in child_scope.declared:
                    self._diag(path, arg_elements.get(name, el), "launch-invalid",
                               f"<include>: unused arg '{name}': {target.name} does not declare it")

    def _tag_node(self, path: Path, el: etree._Element, scope: _Scope, is_test: bool = False) -> None:
        budget.spend("nodes")
        for attr in el.attrib:
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
        if bool_attr(required or "false", "required") and bool_attr(respawn or "false", "respawn"):
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
                          chain=scope.chain, guards=scope.guards)
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
