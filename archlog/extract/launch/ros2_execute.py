"""ROS 2 launch: the actions all three dialects describe, and their static execution into LaunchNodes.

The XML/YAML frontends (ros2_frontend) and the Python reader (ros2_python) turn a file into a
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
import shlex
from collections.abc import Callable, Mapping
from dataclasses import replace
from pathlib import Path
from typing import TypeVar

from archlog import budget, names, sandbox
from archlog.extract.files import unreadable
from archlog.extract.launch.conditions import Guard, guard
from archlog.extract.launch.model import (
    Element,
    LaunchError,
    LaunchHost,
    LaunchNode,
    Nesting,
    SubstitutionError,
    UnknownArg,
    Unresolved,
    include_cycle,
    unresolved_code,
)
from archlog.extract.launch.ros2_actions import (
    Action,
    Component,
    Condition,
    DeclareArgument,
    Description,
    Group,
    Include,
    LoadComponents,
    Node,
    Opaque,
    ParamFile,
    Process,
    PushNamespace,
    SetConfiguration,
    SetEnvironment,
    SetParameter,
    SetParametersFile,
    SetRemap,
    dialect_of,
)
from archlog.extract.launch.ros2_nodes import (
    Ros2Nodes,
    absolute,
    check_namespace,
    global_list,
    namespace_config,
    node_namespace,
    prefix,
    value_or_unknown,
)
from archlog.extract.launch.ros2_subst import Call, Context, Parts, describe, perform, text, trial_value, truth

A = TypeVar("A", bound=Action)
DescribeFile = Callable[[Path, "Ros2Launch"], Description | None]


class Ros2Launch(Ros2Nodes):
    """Runs ROS 2 launch descriptions into the configuration of a host interpreter (sharing its
    element ids, workspace, diagnostics and configuration): the actions that set configurations,
    scopes and includes, and the order and conditions of all of them."""

    def __init__(self, host: LaunchHost, readers: dict[str, DescribeFile]) -> None:
        super().__init__(host)
        self.readers = readers
        self.serial = itertools.count(1)
        self.env: Mapping[str, str | UnknownArg] = {}  # the environment Python launch files see when read
        self._descriptions: dict[tuple[Path, str], Description | None] = {}
        self._real: dict[Path, Path] = {}  # each file's path resolved once (a fan includes one file many times)
        self._nesting = Nesting()  # lists of actions being run (a file, its groups, the files it includes)

    # -- entry points -------------------------------------------------------------------
    def load(self, path: Path, args: dict[str, str | UnknownArg], env: Mapping[str, str | UnknownArg],
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
        if path not in self._real:
            self._real[path] = Path(os.path.realpath(path))
        key = (self._real[path], kind)
        if key not in self._descriptions:
            self._descriptions[key] = self.readers[kind](path, self)
        return self._descriptions[key]

    # -- visiting -----------------------------------------------------------------------
    def run(self, actions: list[Action] | tuple[Action, ...], ctx: Context) -> None:
        with self._nesting.deeper():
            for action in actions:
                self._guarded(action, ctx, self._execute)

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
                crossing = budget.crossed(self.host.display(action.where.file), action.where.line, exc)
            except budget.Crossed as exc:
                crossing = exc
        for read in unseen:
            self.diag(action.where, *sandbox.env_note(read), "note")
        if crossing is None:
            return
        if crossing.final:
            raise crossing
        self.host.report_crossing(crossing)

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
            text, guards = state
            self.diag(action.where, "launch-condition",
                      f"condition {text} cannot be resolved statically; {_label(action)} kept as conditional", "note")
            here = replace(ctx, condition=f"{ctx.condition} and {text}" if ctx.condition else text,
                           guards=(*ctx.guards, *guards))
        try:
            execute(action, here, state is not True)
        except Unresolved as exc:
            self.hole(action.where, unresolved_code(exc, "launch-unknown"), f"{_label(action)} skipped: {exc}")
        except (SubstitutionError, LaunchError) as exc:
            self.diag(action.where, "launch-subst" if isinstance(exc, SubstitutionError) else "launch-invalid",
                      f"{_label(action)}: {exc}", "error")

    def condition(self, conditions: tuple[Condition, ...], ctx: Context) -> bool | tuple[str, tuple[Guard | None, ...]]:
        """False when a condition is false, True when all hold, else the text of those unknown and
        their guards."""
        unknown: list[str] = []
        guards: list[Guard | None] = []
        for cond in conditions:
            def decide(cond: Condition = cond) -> bool:
                return _holds(cond, ctx)

            try:
                if not decide():
                    return False
            except Unresolved as exc:
                unknown.append(f"{cond.describe()} ({exc})")
                guards.append(guard(cond.describe(), decide))
        return (" and ".join(unknown), tuple(guards)) if unknown else True

    def _execute(self, action: Action, ctx: Context, uncertain: bool) -> None:
        if isinstance(action, DeclareArgument):
            self._declare(action, ctx, uncertain)
        elif isinstance(action, SetConfiguration):
            name = perform(action.name, ctx)
            if action.value is None:
                ctx.configs.pop(name, None)
            else:
                ctx.configs[name] = UnknownArg(f"set under {ctx.condition}") if uncertain else \
                    value_or_unknown(action.value, ctx)
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
            global_list(ctx, "global_params").append((name, self._value(action.value, ctx, elem), elem))
        elif isinstance(action, SetParametersFile):
            global_list(ctx, "global_params").append(
                self._param_file(ParamFile(action.path, action.where.line), action.where, ctx))
        elif isinstance(action, Node):
            self._node(action, ctx)
        elif isinstance(action, LoadComponents):
            self._load_components(action, ctx)
        elif isinstance(action, Process):
            self._process(action, ctx)
        elif isinstance(action, Opaque):
            self._opaque(action, ctx)

    def _process(self, action: Process, ctx: Context) -> None:
        """ExecuteProcess (<executable>): a node when it runs a package's executable, named by
        ExecutableInPackage (`$(exec-in-pkg EXE PKG)`) or by `ros2 run PKG EXE`; its name, namespace,
        remaps and parameters come from its own command line only (launch_ros's scope actions set
        those of its Node actions)."""
        started = _package_executable(action.cmd, ctx)
        if started is None:
            shown = " ".join(describe(p) for p in action.cmd)
            self.diag(action.where, "launch-process", f"process `{shown}` is not a ROS node launch_ros starts; "
                      "it is not part of the architecture", "note")
            return
        pkg, exe, rest = started
        own = ctx.scoped()
        for key in ("ros_namespace", "ros_remaps", "global_params"):
            own.configs.pop(key, None)
        self._node(Node(where=action.where, pkg=pkg, exe=exe, arguments=rest), own)

    def _push_namespace(self, action: PushNamespace, ctx: Context, uncertain: bool) -> None:
        """Push a namespace; one that is not known makes the nodes of the scope unknown (they are
        skipped with a diagnostic rather than placed in the wrong namespace)."""
        try:
            if uncertain:
                raise Unresolved(f"pushed under {ctx.condition}")
            combined = absolute(prefix(namespace_config(ctx), perform(action.namespace, ctx)))
        except Unresolved as exc:
            ctx.configs["ros_namespace"] = UnknownArg(str(exc))
            return
        check_namespace(combined)
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
                ctx.configs[action.name] = value_or_unknown(action.default, ctx)
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
                ctx.configs[perform(key, ctx)] = value_or_unknown(value, ctx)
            self.run(action.actions, ctx)
            return
        inner = ctx.scoped()
        kept = {perform(key, ctx): value_or_unknown(value, ctx) for key, value in action.keep}
        if not action.forwarding:
            inner.configs.clear()
        inner.configs.update(kept)
        self.run(action.actions, inner)

    def _include(self, action: Include, ctx: Context) -> None:
        target = Path(perform(action.target, ctx))
        target = target if target.is_absolute() else ctx.file.parent / target
        for key, value in action.args:
            ctx.configs[perform(key, ctx)] = value_or_unknown(value, ctx)
        if (refused := unreadable(target, "launch")) is not None:
            missing = refused.code == "missing"
            self.hole(action.where, "launch-include" if missing else refused.code,
                      f"included file not found: {target}" if missing else f"include skipped: {refused}", "error")
            return
        cycle = include_cycle(self.host.display, target, ctx.file, ctx.chain)
        if cycle is not None:
            self.hole(action.where, "launch-include-cycle", f"include: {target.name} is being launched already "
                      f"({cycle}); launch would recurse until it fails", "error")
            return
        description = self.describe(target, action.dialect)
        if description is None:
            self.config.holes.append((self.host.display(action.where.file), action.where.line,
                                      f"included file {self.host.display(target)} cannot be read"))
            return
        elem = self.element(action.where.file, action.where.line)
        self.run(description, replace(ctx, file=target, chain=(*ctx.chain, elem)))

    def _set_remap(self, action: SetRemap, ctx: Context) -> None:
        src, dst = perform(action.src, ctx), perform(action.dst, ctx)
        elem = self.element(action.where.file, action.where.line)
        global_list(ctx, "ros_remaps").append((src, dst, elem))
        namespace = namespace_config(ctx)
        scope_ns = namespace if isinstance(namespace, str) else "/"
        self.config.scope_remaps.append((elem, names.join(scope_ns, src), names.join(scope_ns, dst)))

    def _opaque(self, action: Opaque, ctx: Context) -> None:
        if action.run is None:
            self.hole(action.where, "launch-unknown", f"{action.reason}: not interpreted; the nodes it may start "
                      "are not part of this configuration")
            return
        self.run(action.run(ctx), ctx)

    # -- nodes and components -------------------------------------------------------------
    def _node(self, action: Node, ctx: Context) -> None:
        budget.spend("nodes")
        pkg = perform(action.pkg, ctx) if action.pkg is not None else ""
        exe = perform(action.exe, ctx)
        elem = self.element(action.where.file, action.where.line)
        base = self._base_name(action.name, action.where, ctx)
        namespace = node_namespace(action.namespace, ctx)
        words = [self._word(a, ctx) for a in action.arguments]
        ros_words = [self._word(a, ctx) for a in action.ros_arguments] if action.ros_arguments is not None else None
        command = words + (["--ros-args", *ros_words] if ros_words is not None else [])
        arg_remaps, arg_params, renamed = self._ros_args(command, base, elem, action.where, ctx)
        base = renamed.get("__node", base)
        if "__ns" in renamed:
            namespace = absolute(renamed["__ns"])
        full = names.join(namespace or "/", base) if base else ""
        remaps = arg_remaps + self._scope_remaps(ctx) + self._remaps(action.remaps, action.where, ctx)
        params = arg_params + self._scope_params(ctx) + self._params(action.params, action.where, ctx)
        node = LaunchNode(elem, pkg, exe, full, namespace or "", remaps, ctx.condition, shlex.join(words),
                          declared=full, chain=ctx.chain, parameters=params, ros2=True, guards=ctx.guards)
        self.config.nodes.append(node)
        self._launched[id(action)] = full
        for component in action.components:
            self._guarded(component, ctx, lambda c, here, _: self._component(c, full, here))

    def _load_components(self, action: LoadComponents, ctx: Context) -> None:
        if isinstance(action.target, Node):
            if id(action.target) not in self._launched:
                raise LaunchError("its target container has not been started")
            manager = self._launched[id(action.target)]
        else:
            manager = names.join("/", perform(action.target, ctx))
        for component in action.components:
            self._guarded(component, ctx, lambda c, here, _: self._component(c, manager, here))


def _package_executable(cmd: tuple[Parts, ...], ctx: Context) -> tuple[Parts, Parts, tuple[Parts, ...]] | None:
    """(package, executable, the words after it) of a command that runs a package's executable:
    `$(exec-in-pkg EXE PKG) ARGS...` or `ros2 run PKG EXE ARGS...` (ros2 written, or found with
    FindExecutable); None for any other command."""
    first = cmd[0] if cmd else ()
    if len(first) == 1 and isinstance(first[0], Call) and first[0].name == "exec-in-pkg" and len(first[0].args) == 2:
        exe, pkg = first[0].args
        return pkg, exe, cmd[1:]
    if len(cmd) == 1 and not any(isinstance(p, Call) for p in first):  # one string: the words of a shell command
        cmd = tuple(text(word) for word in shlex.split(perform(first, ctx)))
    program = cmd[0] if cmd else ()
    runs = len(program) == 1 and isinstance(program[0], Call) and program[0].name == "find-exec" and \
        [perform(a, ctx) for a in program[0].args] == ["ros2"] or \
        not any(isinstance(p, Call) for p in program) and perform(program, ctx).rsplit("/", 1)[-1] == "ros2"
    if runs and len(cmd) >= 4 and perform(cmd[1], ctx) == "run":
        return cmd[2], cmd[3], cmd[4:]
    return None


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
        value = trial_value(cond.name, value)
    expected = None if cond.expr is None else perform(cond.expr, ctx)
    equal = value == expected if cond.name in ctx.configs else expected is None
    return equal if cond.kind == "equals" else not equal


