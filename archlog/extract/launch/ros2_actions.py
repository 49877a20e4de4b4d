"""ROS 2 launch actions: what the XML, YAML and Python dialects describe a launch file as, for
the executor (archlog.extract.launch.ros2_execute) to run."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from archlog.extract.launch.ros2_subst import Context, Parts, describe, text

PYTHON, XML, YAML = "python", "xml", "yaml"


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


def dialect_of(path: Path) -> str:
    """The dialect a launch file's name announces (AnyLaunchDescriptionSource's guess)."""
    if path.suffix == ".py":
        return PYTHON
    if path.suffix in (".yaml", ".yml"):
        return YAML
    return XML

