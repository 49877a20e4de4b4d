"""ROS 2 launch: the actions all three dialects describe, and their static execution into LaunchNodes.

The XML/YAML frontends (launch2_frontend) and the Python reader (launch2_python) turn a file into a
list of actions; `Ros2Launch` visits them in order as launch does, with launch's scoping: a group
is scoped by default (it copies the launch configurations, so `ros_namespace`, `ros_remaps` and
`global_params`, which launch_ros keeps there, are scoped too, and the lists in them are shared as
launch shares them); an include is not scoped (its arguments and what it sets stay set). A node's
namespace is launch_ros's: a relative one is appended to the pushed one, an absolute one replaces
it. Its remaps and parameters come in command-line order: those in its own arguments, then the
scope's (set_remap, set_parameter), then its own. rcl applies the first remap that matches.

Within the launch configuration's budget (archlog.budget), each action visited counts as an
element and each nested list of actions (group, include, OpaqueFunction) as a level of depth;
including a file that is being run already (a cycle, where launch would recurse until it
fails) is refused.
"""

from __future__ import annotations

import itertools
import os
import re
import shlex
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TypeVar

from archlog import budget, names, sandbox
from archlog.extract.launch import Element, LaunchError, LaunchInterpreter, LaunchNode
from archlog.extract.launch2_subst import (Context, Parts, Rewritten, describe, parse, perform, text, truth,
                                          typed_bool, unknown_reason, yaml_value)
from archlog.extract.ros2_params import load_param_file
from archlog.extract.files import unreadable
from archlog.extract.substitution import (RefusedRead, SubstitutionError, UnknownArg, Unresolved, read_file,
                                          unresolved_code)
from archlog.values import Unknown

PYTHON, XML, YAML = "python", "xml", "yaml"
_NODE_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_NAMESPACE = re.compile(r"/|(/[A-Za-z_][A-Za-z0-9_]*)+")


@dataclass(frozen=True)
class Where:
    """Where an action is written."""

    file: Path
    line: int


@dataclass(frozen=True)
class Condition:
    """`if`/`unless` over an expression, LaunchConfigurationEquals/NotEquals (`name` and the
    expected value, None for "not set"), or `guard`: a Python branch archlog cannot decide."""

    kind: str
    expr: Parts | None
    name: str = ""

    def describe(self) -> str:
        if self.kind in ("if", "unless"):
            return f'{self.kind}="{describe(self.expr or ())}"'
        if self.kind == "guard":
            return describe(self.expr or ())
        expected = "<unset>" if self.expr is None else describe(self.expr)
        return f"{self.name} {'==' if self.kind == 'equals' else '!='} {expected}"


@dataclass(frozen=True, kw_only=True)
class Action:
    where: Where
    conditions: tuple[Condition, ...] = ()


@dataclass(frozen=True)
class ParamText:
    """A parameter value given by substitutions: performed, then read with YAML rules (or coerced
    to `kind`: str, int, float, bool, list_of_*)."""

    parts: Parts
    kind: str | None = None


@dataclass(frozen=True)
class ParamItem:
    name: Parts
    value: object  # a literal (str stays str), a list of literals, ParamText, or a list of ParamText
    line: int


@dataclass(frozen=True)
class ParamDict:
    """A dictionary of parameters (or one <param>), names already dotted."""

    items: tuple[ParamItem, ...]


@dataclass(frozen=True)
class ParamFile:
    path: Parts  # a single Rewritten part: nav2's RewrittenYaml
    line: int
    allow_substs: Parts | bool = False


ParamSource = ParamDict | ParamFile


@dataclass(frozen=True)
class Remap:
    src: Parts
    dst: Parts
    line: int


@dataclass(frozen=True, kw_only=True)
class DeclareArgument(Action):
    name: str
    default: Parts | None = None
    choices: tuple[str, ...] | None = None


@dataclass(frozen=True, kw_only=True)
class SetConfiguration(Action):
    name: Parts
    value: Parts | None  # None: unset


@dataclass(frozen=True, kw_only=True)
class SetEnvironment(Action):
    name: Parts
    value: Parts | None  # None: unset
    append: str = ""  # "" to set, else "append" or "prepend"
    separator: Parts = text(":")


@dataclass(frozen=True, kw_only=True)
class Group(Action):
    actions: tuple[Action, ...]
    scoped: bool = True
    forwarding: bool = True
    keep: tuple[tuple[Parts, Parts], ...] = ()


@dataclass(frozen=True, kw_only=True)
class Include(Action):
    target: Parts
    args: tuple[tuple[Parts, Parts], ...] = ()
    dialect: str | None = None  # None: by the file name, as AnyLaunchDescriptionSource


@dataclass(frozen=True, kw_only=True)
class PushNamespace(Action):
    namespace: Parts


@dataclass(frozen=True, kw_only=True)
class SetRemap(Action):
    src: Parts
    dst: Parts


@dataclass(frozen=True, kw_only=True)
class SetParameter(Action):
    name: Parts
    value: object


@dataclass(frozen=True, kw_only=True)
class SetParametersFile(Action):
    path: Parts


@dataclass(frozen=True, kw_only=True)
class Component(Action):
    """A composable node description (its own condition, if any, is evaluated at load time)."""

    pkg: Parts
    plugin: Parts
    name: Parts | None = None
    namespace: Parts | None = None
    params: tuple[ParamSource, ...] = ()
    remaps: tuple[Remap, ...] = ()


@dataclass(frozen=True, kw_only=True, eq=False)
class Node(Action):
    """launch_ros's Node (and LifecycleNode); with `components`, a ComposableNodeContainer."""

    pkg: Parts | None
    exe: Parts
    name: Parts | None = None
    namespace: Parts | None = None
    params: tuple[ParamSource, ...] = ()
    remaps: tuple[Remap, ...] = ()
    arguments: tuple[Parts, ...] = ()
    ros_arguments: tuple[Parts, ...] | None = None
    components: tuple[Component, ...] = ()


@dataclass(frozen=True, kw_only=True)
class LoadComponents(Action):
    target: Parts | Node
    components: tuple[Component, ...]


@dataclass(frozen=True, kw_only=True)
class Process(Action):
    """A process that is not a ROS node as far as launch knows (ExecuteProcess, <executable>)."""

    cmd: tuple[Parts, ...]


@dataclass(frozen=True, kw_only=True)
class Opaque(Action):
    """What archlog cannot read ahead of time: an OpaqueFunction (`run` gives its actions in a
    context, or raises Unresolved) or an entity it cannot interpret (`run` is None)."""

    reason: str
    run: Callable[[Context], list[Action]] | None = field(default=None, compare=False)


Description = list[Action]
A = TypeVar("A", bound=Action)
DescribeFile = Callable[[Path, "Ros2Launch"], Description | None]


class Ros2Launch:
    """Runs ROS 2 launch descriptions into the configuration of a LaunchInterpreter (sharing its
    element ids, workspace, diagnostics and configuration)."""

    def __init__(self, interp: LaunchInterpreter, readers: dict[str, DescribeFile]) -> None:
        self.interp = interp
        self.workspace = interp.workspace
        self.diagnostics = interp.diagnostics
        self.config = interp.config
        self.readers = readers
        self.serial = itertools.count(1)
        self.env: dict[str, str | UnknownArg] = {}  # the environment Python launch files see when read
        self._descriptions: dict[tuple[Path, str], Description | None] = {}
        self._param_files: dict[tuple[Path, str | None], list[tuple[str, str, object, Element]]] = {}
        self._templates: dict[Path, Parts] = {}  # parameter files read as substitutions
        self._launched: dict[int, str] = {}  # id of a container's Node action -> its full name
        self._nesting = 0  # lists of actions being run (a file, its groups, the files it includes)

    # -- entry points -------------------------------------------------------------------
    def load(self, path: Path, args: dict[str, str | UnknownArg], env: dict[str, str | UnknownArg],
             chain: tuple[Element, ...] = ()) -> bool:
        """Launch one file as `ros2 launch FILE name:=value...` would; False when it cannot be read."""
        self.env = env
        description = self.describe(path, None)
        if description is None:
            return False
        ctx = Context(dict(args), dict(env), path, self.workspace.find, self.serial, chain=chain)
        self.run(description, ctx)
        return True

    def describe(self, path: Path, dialect: str | None) -> Description | None:
        """A file's description, read once (descriptions do not depend on the context)."""
        kind = dialect or dialect_of(path)
        key = (Path(os.path.realpath(path)), kind)
        if key not in self._descriptions:
            self._descriptions[key] = self.readers[kind](path, self)
        return self._descriptions[key]

    def diag(self, where: Where, code: str, message: str, severity: str = "warning") -> None:
        self.diagnostics.add(self.interp.display(where.file), where.line, code, message, severity)

    def element(self, file: Path, line: int) -> Element:
        return self.interp.element_at(file, line)

    # -- visiting -----------------------------------------------------------------------
    def run(self, actions: list[Action] | tuple[Action, ...], ctx: Context) -> None:
        budget.current().check("depth", self._nesting + 1)
        self._nesting += 1
        try:
            for action in actions:
                self._guarded(action, ctx, self._execute)
        finally:
            self._nesting -= 1

    def _guarded(self, action: A, ctx: Context, execute: Callable[[A, Context, bool], None]) -> None:
        """Execute an action whose conditions hold (kept as conditional when they cannot be known;
        `execute` is told so); what it cannot do is a diagnostic at the action, a limit of the
        budget crossed inside it (and not deeper) is crossed there, and each environment variable it
        read that the run was not given is noted there."""
        crossing: budget.Crossed | None = None
        with sandbox.reads_not_given() as unseen:
            try:
                budget.spend("elements")
                self._within(action, ctx, execute)
            except (budget.BudgetExceeded, RecursionError, MemoryError) as exc:
                crossing = budget.crossed(self.interp.display(action.where.file), action.where.line, exc)
            except budget.Crossed as exc:
                crossing = exc
        for name in unseen:
            self.diag(action.where, "env-not-given", sandbox.not_given_message(name), "note")
        if crossing is None:
            return
        if crossing.final:
            raise crossing
        self.interp.report_crossing(crossing)

    def _within(self, action: A, ctx: Context, execute: Callable[[A, Context, bool], None]) -> None:
        try:
            state = self.condition(action.conditions, ctx)
        except (SubstitutionError, LaunchError) as exc:
            self.diag(action.where, "launch-subst", f"condition of {_label(action)}: {exc}", "error")
            return
        if state is False:
            return
        here = ctx
        if state is not True:
            self.diag(action.where, "launch-condition",
                      f"condition {state} cannot be resolved statically; {_label(action)} kept as conditional", "note")
            here = replace(ctx, condition=f"{ctx.condition} and {state}" if ctx.condition else state)
        try:
            execute(action, here, state is not True)
        except Unresolved as exc:
            self.diag(action.where, unresolved_code(exc, "launch-unknown"), f"{_label(action)} skipped: {exc}")
        except (SubstitutionError, LaunchError) as exc:
            self.diag(action.where, "launch-subst" if isinstance(exc, SubstitutionError) else "launch-invalid",
                      f"{_label(action)}: {exc}", "error")

    def condition(self, conditions: tuple[Condition, ...], ctx: Context) -> bool | str:
        """False when a condition is false, True when all hold, else the text of those unknown."""
        unknown = []
        for cond in conditions:
            try:
                if not _holds(cond, ctx):
                    return False
            except Unresolved as exc:
                unknown.append(f"{cond.describe()} ({exc})")
        return " and ".join(unknown) if unknown else True

    def _execute(self, action: Action, ctx: Context, uncertain: bool) -> None:
        if isinstance(action, DeclareArgument):
            self._declare(action, ctx, uncertain)
        elif isinstance(action, SetConfiguration):
            name = perform(action.name, ctx)
            if action.value is None:
                ctx.configs.pop(name, None)
            else:
                ctx.configs[name] = UnknownArg(f"set under {ctx.condition}") if uncertain else \
                    _value_or_unknown(action.value, ctx)
        elif isinstance(action, SetEnvironment):
            self._environment(action, ctx, uncertain)
        elif isinstance(action, Group):
            self._group(action, ctx)
        elif isinstance(action, Include):
            self._include(action, ctx)
        elif isinstance(action, PushNamespace):
            self._push_namespace(action, ctx, uncertain)
        elif isinstance(action, SetRemap):
            self._set_remap(action, ctx)
        elif isinstance(action, SetParameter):
            elem = self.element(action.where.file, action.where.line)
            name = perform(action.name, ctx)
            _global_list(ctx, "global_params").append((name, self._value(action.value, ctx, elem), elem))
        elif isinstance(action, SetParametersFile):
            _global_list(ctx, "global_params").append(
                self._param_file(ParamFile(action.path, action.where.line), action.where, ctx))
        elif isinstance(action, Node):
            self._node(action, ctx)
        elif isinstance(action, LoadComponents):
            self._load_components(action, ctx)
        elif isinstance(action, Process):
            shown = " ".join(describe(p) for p in action.cmd)
            self.diag(action.where, "launch-process", f"process `{shown}` is not a ROS node launch_ros starts; "
                      "it is not part of the architecture", "note")
        elif isinstance(action, Opaque):
            self._opaque(action, ctx)

    def _push_namespace(self, action: PushNamespace, ctx: Context, uncertain: bool) -> None:
        """Push a namespace; one that is not known makes the nodes of the scope unknown (they are
        skipped with a diagnostic rather than placed in the wrong namespace)."""
        try:
            if uncertain:
                raise Unresolved(f"pushed under {ctx.condition}")
            combined = _absolute(_prefix(_namespace_config(ctx), perform(action.namespace, ctx)))
        except Unresolved as exc:
            ctx.configs["ros_namespace"] = UnknownArg(str(exc))
            return
        _check_namespace(combined)
        ctx.configs["ros_namespace"] = combined

    def _declare(self, action: DeclareArgument, ctx: Context, uncertain: bool) -> None:
        if action.name not in ctx.configs:
            if uncertain:
                ctx.configs[action.name] = UnknownArg(f"declared under {ctx.condition}")
            elif action.default is None:
                ctx.configs[action.name] = UnknownArg("no default and not given")
                self.diag(action.where, "launch-arg-unknown", f"launch argument '{action.name}' has no default and "
                          "is not given; pass it with --arg", "note")
            else:
                ctx.configs[action.name] = _value_or_unknown(action.default, ctx)
        value = ctx.configs[action.name]
        if action.choices is not None and isinstance(value, str) and value not in action.choices:
            raise LaunchError(f"argument '{action.name}' is {value!r}, not one of {', '.join(action.choices)}")

    def _environment(self, action: SetEnvironment, ctx: Context, uncertain: bool) -> None:
        """set_env, unset_env, append_env; a value that is not known leaves the variable unknown."""
        name = perform(action.name, ctx)
        if action.value is None and not uncertain:
            ctx.env.pop(name, None)
            return
        try:
            if uncertain:
                raise Unresolved(f"set under {ctx.condition}")
            value = perform(action.value or (), ctx)
            old = ctx.env.get(name)
            if action.append and name not in ctx.env:
                sandbox.not_given(name)  # appended to the value the machine would have
            if action.append and old:
                if isinstance(old, UnknownArg):
                    raise Unresolved(old.reason)
                sep = perform(action.separator, ctx)
                value = f"{value}{sep}{old}" if action.append == "prepend" else f"{old}{sep}{value}"
            ctx.env[name] = value
        except Unresolved as exc:
            ctx.env[name] = UnknownArg(str(exc))

    def _group(self, action: Group, ctx: Context) -> None:
        if not action.scoped:
            for key, value in action.keep:
                ctx.configs[perform(key, ctx)] = _value_or_unknown(value, ctx)
            self.run(action.actions, ctx)
            return
        inner = ctx.scoped()
        kept = {perform(key, ctx): _value_or_unknown(value, ctx) for key, value in action.keep}
        if not action.forwarding:
            inner.configs.clear()
        inner.configs.update(kept)
        self.run(action.actions, inner)

    def _include(self, action: Include, ctx: Context) -> None:
        target = Path(perform(action.target, ctx))
        target = target if target.is_absolute() else ctx.file.parent / target
        for key, value in action.args:
            ctx.configs[perform(key, ctx)] = _value_or_unknown(value, ctx)
        if (refused := unreadable(target, "launch")) is not None:
            missing = refused.code == "missing"
            self.diag(action.where, "launch-include" if missing else refused.code,
                      f"included file not found: {target}" if missing else f"include skipped: {refused}", "error")
            return
        cycle = self.interp.include_cycle(target, ctx.file, ctx.chain)
        if cycle is not None:
            self.diag(action.where, "launch-include-cycle", f"include: {target.name} is being launched already "
                      f"({cycle}); launch would recurse until it fails", "error")
            return
        description = self.describe(target, action.dialect)
        if description is None:
            return
        elem = self.element(action.where.file, action.where.line)
        self.run(description, replace(ctx, file=target, chain=(*ctx.chain, elem)))

    def _set_remap(self, action: SetRemap, ctx: Context) -> None:
        src, dst = perform(action.src, ctx), perform(action.dst, ctx)
        elem = self.element(action.where.file, action.where.line)
        _global_list(ctx, "ros_remaps").append((src, dst, elem))
        namespace = _namespace_config(ctx)
        scope_ns = namespace if isinstance(namespace, str) else "/"
        self.config.scope_remaps.append((elem, names.join(scope_ns, src), names.join(scope_ns, dst)))

    def _opaque(self, action: Opaque, ctx: Context) -> None:
        if action.run is None:
            self.diag(action.where, "launch-unknown", f"{action.reason}: not interpreted; the nodes it may start "
                      "are not part of this configuration")
            return
        self.run(action.run(ctx), ctx)

    # -- nodes --------------------------------------------------------------------------
    def _node(self, action: Node, ctx: Context) -> None:
        pkg = perform(action.pkg, ctx) if action.pkg is not None else ""
        exe = perform(action.exe, ctx)
        elem = self.element(action.where.file, action.where.line)
        base = self._base_name(action.name, action.where, ctx)
        namespace = _node_namespace(action.namespace, ctx)
        words = [self._word(a, ctx) for a in action.arguments]
        ros_words = [self._word(a, ctx) for a in action.ros_arguments] if action.ros_arguments is not None else None
        command = words + (["--ros-args", *ros_words] if ros_words is not None else [])
        arg_remaps, arg_params, renamed = self._ros_args(command, base, elem, action.where, ctx)
        base = renamed.get("__node", base)
        if "__ns" in renamed:
            namespace = _absolute(renamed["__ns"])
        full = names.join(namespace or "/", base) if base else ""
        remaps = arg_remaps + self._scope_remaps(ctx) + self._remaps(action.remaps, action.where, ctx)
        params = arg_params + self._scope_params(ctx) + self._params(action.params, action.where, ctx)
        node = LaunchNode(elem, pkg, exe, full, namespace or "", remaps, ctx.condition, shlex.join(words), declared=full,
                          chain=ctx.chain, parameters=params, ros2=True)
        self.config.nodes.append(node)
        self._launched[id(action)] = full
        for component in action.components:
            self._guarded(component, ctx, lambda c, here, _: self._component(c, full, here))

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
            return []
        if (refused := unreadable(path, "params")) is not None:
            missing = refused.code == "missing"
            self.diag(replace(where, line=source.line), "param-file" if missing else refused.code,
                      f"parameter file not found: {path}" if missing else f"parameter file skipped: {refused}")
            return []
        substitute = source.allow_substs if isinstance(source.allow_substs, bool) else \
            typed_bool(perform(source.allow_substs, ctx))
        content = self._substituted(path, where, ctx) if substitute else None
        key = (Path(os.path.realpath(path)), content)
        if key not in self._param_files:
            shown = self.interp.display(path)
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
    def _load_components(self, action: LoadComponents, ctx: Context) -> None:
        if isinstance(action.target, Node):
            if id(action.target) not in self._launched:
                raise LaunchError("its target container has not been started")
            manager = self._launched[id(action.target)]
        else:
            manager = names.join("/", perform(action.target, ctx))
        for component in action.components:
            self._guarded(component, ctx, lambda c, here, _: self._component(c, manager, here))

    def _component(self, component: Component, manager: str, ctx: Context) -> None:
        pkg, plugin = perform(component.pkg, ctx), perform(component.plugin, ctx)
        elem = self.element(component.where.file, component.where.line)
        base = self._base_name(component.name, component.where, ctx)
        namespace = _node_namespace(component.namespace, ctx)
        full = names.join(namespace or "/", base) if base else ""
        remaps = self._scope_remaps(ctx) + self._remaps(component.remaps, component.where, ctx)
        key = f"{namespace.strip('/')}/{base}" if namespace and namespace != "/" else base
        params = self._scope_params(ctx, key) + self._params(component.params, component.where, ctx, key)
        self.config.nodes.append(LaunchNode(elem, pkg, plugin, full, namespace or "", remaps, ctx.condition,
                                            plugin=plugin, manager=manager, declared=full, chain=ctx.chain,
                                            parameters=params, ros2=True))


def dialect_of(path: Path) -> str:
    """The dialect a launch file's name announces (AnyLaunchDescriptionSource's guess)."""
    if path.suffix == ".py":
        return PYTHON
    if path.suffix in (".yaml", ".yml"):
        return YAML
    return XML


def _label(action: Action) -> str:
    """What an action is called in messages (its frontend tag, which names the Python class too)."""
    return {DeclareArgument: "arg", SetConfiguration: "let", SetEnvironment: "set_env", Group: "group",
            Include: "include", PushNamespace: "push-ros-namespace", SetRemap: "set_remap",
            SetParameter: "set_parameter", SetParametersFile: "set_parameters_from_file", Node: "node",
            LoadComponents: "load_composable_node", Process: "executable", Opaque: "OpaqueFunction",
            Component: "composable_node"}.get(type(action), type(action).__name__)


def _holds(cond: Condition, ctx: Context) -> bool:
    if cond.kind == "if":
        return truth(cond.expr or (), ctx)
    if cond.kind == "unless":
        return not truth(cond.expr or (), ctx)
    if cond.kind == "guard":
        raise Unresolved("a Python test on values not known statically")
    value = ctx.configs.get(cond.name)
    if isinstance(value, UnknownArg):
        raise Unresolved(unknown_reason(cond.name, value))
    expected = None if cond.expr is None else perform(cond.expr, ctx)
    equal = value == expected if cond.name in ctx.configs else expected is None
    return equal if cond.kind == "equals" else not equal


def _value_or_unknown(parts: Parts, ctx: Context) -> str | UnknownArg:
    try:
        return perform(parts, ctx)
    except Unresolved as exc:
        return UnknownArg(str(exc))


def _global_list(ctx: Context, key: str) -> list:
    """launch_ros's scope lists: taken from the configurations, created when absent."""
    current = ctx.configs.get(key)
    if not isinstance(current, list):
        current = []
        ctx.configs[key] = current
    return current


def _namespace_config(ctx: Context) -> str | None:
    value = ctx.configs.get("ros_namespace")
    if isinstance(value, UnknownArg):
        raise Unresolved(f"the pushed namespace is not known ({unknown_reason('ros_namespace', value)})")
    return None if value is None else str(value)


def _prefix(base: str | None, ns: str | None) -> str | None:
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


def _absolute(ns: str | None) -> str | None:
    if ns is None:
        return None
    return ns if ns.startswith("/") else "/" + ns


def _check_namespace(ns: str | None) -> None:
    if ns is not None and not _NAMESPACE.fullmatch(ns):
        raise LaunchError(f"invalid namespace {ns!r}")


def _node_namespace(namespace: Parts | None, ctx: Context) -> str | None:
    """A node's namespace: its own under the pushed one; None when neither is set."""
    own = perform(namespace, ctx) if namespace is not None else None
    combined = _absolute(own if own is not None and own.startswith("/") else _prefix(_namespace_config(ctx), own))
    _check_namespace(combined)
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
            try:
                return float(value) if "." in value else int(value)
            except ValueError:
                pass
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

