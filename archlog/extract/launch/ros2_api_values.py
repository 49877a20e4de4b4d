"""The values a static reading of a Python launch file holds for what the launch and launch_ros
API build (launch objects, substitutions, Unread), and their conversion into ROS 2 launch actions
(archlog.extract.launch.ros2_actions)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Protocol

from archlog.extract.launch.model import LaunchError, RefusedRead, UnknownArg
from archlog.extract.launch.ros2_actions import (
    Action,
    Component,
    Condition,
    Opaque,
    ParamDict,
    ParamFile,
    ParamItem,
    ParamSource,
    ParamText,
    Remap,
    Where,
)
from archlog.extract.launch.ros2_subst import Context, Parts, Text, opaque, text
from archlog.sandbox import NotGiven

MAX_RANGE = 10_000


# -- values -------------------------------------------------------------------------------
@dataclass(frozen=True)
class Unread:
    """A value archlog cannot know ahead of time, with the reason and where it was met."""

    reason: str
    line: int


@dataclass(frozen=True)
class Ref:
    """An imported module, class or function, by its qualified name."""

    name: str


@dataclass(frozen=True)
class S:
    """A launch substitution object (or a SomeSubstitutionsType list of them)."""

    parts: Parts


@dataclass
class Description:
    """A LaunchDescription under construction."""

    actions: list[object] = field(default_factory=list)


class LineDict(dict):
    """A dict literal that remembers the line of each key."""

    lines: dict[object, int]


class LineTuple(tuple):
    """A tuple literal that remembers its line."""

    line: int


@dataclass(frozen=True)
class PathValue:
    """A pathlib.Path."""

    path: str


@dataclass(frozen=True)
class FileHandle:
    """A file opened for reading."""

    path: str


@dataclass(frozen=True)
class ContextValue:
    """The LaunchContext an OpaqueFunction receives."""

    ctx: Context


@dataclass(frozen=True)
class ConfigsView:
    """context.launch_configurations."""

    ctx: Context


@dataclass(frozen=True)
class Source:
    """A launch description source: the file and its dialect (None: by its name)."""

    target: Parts
    dialect: str | None


@dataclass(frozen=True)
class Typed:
    """launch_ros's ParameterValue (or Parameter, with a name): a value and its declared type."""

    value: object
    kind: str | None
    name: Parts | None = None


@dataclass(frozen=True)
class Handler:
    """An event handler (OnProcessExit, ...): the actions it starts, or a callable."""

    actions: object


class Interpreter(Protocol):
    """What API calls need from the interpreter of the file."""

    path: Path
    env: Mapping[str, str | UnknownArg]
    guards: list[Condition]

    def find(self, pkg: str) -> Path | None: ...

    def site(self, line: int) -> int: ...

    def not_given(self, read: NotGiven, line: int) -> None: ...

    def refused_read(self, exc: RefusedRead, line: int) -> None:
        """Report a file the sandbox will not read, named at `line`."""

    def call(self, function: object, args: list[object], kwargs: dict[str, object], line: int) -> object: ...


@dataclass
class CallSite:
    """One call of an API function: its arguments, line and interpreter."""

    args: list[object]
    kwargs: dict[str, object]
    line: int
    interp: Interpreter

    def arg(self, index: int, name: str, default: object = None) -> object:
        """An argument given by position or keyword."""
        if name in self.kwargs:
            return self.kwargs[name]
        return self.args[index] if index < len(self.args) else default

    def where(self) -> Where:
        return Where(self.interp.path, self.interp.site(self.line))

    def conditions(self) -> tuple[Condition, ...]:
        """The action's `condition=` and the Python branches it was created in."""
        own = self.kwargs.get("condition")
        found = list(self.interp.guards)
        if isinstance(own, Condition):
            found.append(own)
        elif own is not None:
            found.append(Condition("guard", to_parts(own, self.line)))
        return tuple(found)


# -- conversions --------------------------------------------------------------------------
def to_parts(value: object, line: int) -> Parts:
    """A SomeSubstitutionsType value as parts (numbers are written out, as launch users expect)."""
    if isinstance(value, str):
        return text(value)
    if isinstance(value, S):
        return value.parts
    if isinstance(value, PathValue):
        return text(value.path)
    if isinstance(value, bool):
        return text(str(value).lower())
    if isinstance(value, (int, float)):
        return text(str(value))
    if isinstance(value, (list, tuple)):
        return tuple(p for item in value for p in to_parts(item, line))
    if isinstance(value, Unread):
        return opaque(f"{value.reason} (line {value.line})")
    return opaque(f"a {type(value).__name__} where text was expected (line {line})")


def optional_parts(value: object, line: int) -> Parts | None:
    return None if value is None else to_parts(value, line)


def entities(value: object, where: Where) -> list[Action]:
    """The actions of a LaunchDescription, a list of entities, or one entity."""
    if isinstance(value, Description):
        return entities(value.actions, where)
    if isinstance(value, (list, tuple)):
        return [a for item in value for a in entities(item, where)]
    if isinstance(value, Action):
        return [value]
    if value is None:
        return []
    if isinstance(value, Unread):
        return [Opaque(where=Where(where.file, value.line), reason=value.reason)]
    return [Opaque(where=where, reason=f"a {type(value).__name__} is not a launch entity")]


def listed(value: object) -> list[object]:
    if value is None:
        return []
    return list(value) if isinstance(value, (list, tuple)) else [value]


def description_source(value: object, line: int) -> Source:
    return value if isinstance(value, Source) else Source(to_parts(value, line), None)


def include_args(value: object, line: int) -> tuple[tuple[Parts, Parts], ...]:
    """launch_arguments: pairs, or a dict (its items)."""
    if isinstance(value, dict):
        value = list(value.items())
    if value is None:
        return ()
    if not isinstance(value, (list, tuple)):
        raise LaunchError(f"launch_arguments is not known statically ({why(value)})")
    pairs = []
    for item in value:
        if not isinstance(item, (list, tuple)) or len(item) != 2:
            raise LaunchError(f"launch argument {item!r} is not a (name, value) pair")
        pairs.append((to_parts(item[0], line), to_parts(item[1], line)))
    return tuple(pairs)


def why(value: object) -> str:
    return value.reason if isinstance(value, Unread) else type(value).__name__


def remap_list(value: object, line: int) -> tuple[Remap, ...]:
    if value is None:
        return ()
    if not isinstance(value, (list, tuple)):
        return (Remap(opaque(f"remappings not known statically ({why(value)})"), text(""), line),)
    found = []
    for item in value:
        at = getattr(item, "line", line)
        if isinstance(item, (list, tuple)) and len(item) == 2:
            found.append(Remap(to_parts(item[0], at), to_parts(item[1], at), at))
        else:
            found.append(Remap(opaque(f"remapping not known statically ({why(item)})"), text(""), at))
    return tuple(found)


def command_words(value: object, line: int) -> tuple[Parts, ...]:
    if value is None:
        return ()
    if not isinstance(value, (list, tuple)):
        return (to_parts(value, line),)
    return tuple(to_parts(item, line) for item in value)


_TYPES = {"str": "str", "int": "int", "float": "float", "bool": "bool", "List[str]": "list_of_str",
          "List[int]": "list_of_int", "List[float]": "list_of_float", "List[bool]": "list_of_bool"}


def value_kind(value: object) -> str | None:
    """A ParameterValue's value_type (str, int, List[int]...) by its name."""
    if isinstance(value, Ref):
        return _TYPES.get(value.name.rpartition(".")[2]) or _TYPES.get(value.name)
    if isinstance(value, type):
        return _TYPES.get(value.__name__)
    return None


def param_value(value: object, line: int) -> object:
    """A Python parameter value as launch_ros normalizes it: text stays text, substitutions are
    read with YAML rules, lists become uniform."""
    if isinstance(value, Typed):
        if isinstance(value.value, (S, list, tuple)) and _has_subst(value.value):
            return ParamText(to_parts(value.value, line), value.kind)
        return value.value
    if isinstance(value, (S, Unread)):
        return ParamText(to_parts(value, line))
    if isinstance(value, PathValue):
        return value.path
    if isinstance(value, (list, tuple)):
        items = list(value)
        kinds = {type(v) for v in items}
        if items and _has_subst(items) and all(isinstance(v, (str, S)) for v in items):
            return ParamText(to_parts(items, line))
        if kinds == {int} or kinds == {bool} or kinds == {str}:
            return items
        if kinds <= {int, float} and items:
            return [float(v) for v in items]
        return [v if isinstance(v, (str, int, float, bool)) else param_value(v, line) for v in items]
    if value is None:
        return ParamText(opaque(f"None as a parameter value (line {line})"))
    return value


def _has_subst(value: object) -> bool:
    if isinstance(value, (list, tuple)):
        return any(_has_subst(v) for v in value)
    return isinstance(value, (S, Unread))


def _dict_items(value: dict, prefix: Parts, line: int) -> list[ParamItem]:
    """A parameter dict flattened: nested dicts give dotted names."""
    items = []
    lines = getattr(value, "lines", {})
    for key, item in value.items():
        at = lines.get(key, line)
        name = to_parts(key, at)
        full = (*prefix, Text("."), *name) if prefix else name
        if isinstance(item, dict):
            items.extend(_dict_items(item, full, at))
        else:
            items.append(ParamItem(full, param_value(item, at), at))
    return items


def params(value: object, line: int) -> tuple[ParamSource, ...]:
    """A node's `parameters` list: dicts, Parameter descriptions and parameter files."""
    if value is None:
        return ()
    if not isinstance(value, (list, tuple)):
        return (ParamDict((ParamItem(opaque(f"parameters not known statically ({why(value)})"), None, line),)),)
    found: list[ParamSource] = []
    for item in value:
        if isinstance(item, dict):
            found.append(ParamDict(tuple(_dict_items(item, (), line))))
        elif isinstance(item, ParamFile):
            found.append(item)
        elif isinstance(item, Typed) and item.name is not None:
            found.append(ParamDict((ParamItem(item.name, param_value(item, line), line),)))
        elif isinstance(item, Unread):
            found.append(ParamDict((ParamItem(opaque(f"{item.reason} (line {item.line})"), None, line),)))
        else:
            found.append(ParamFile(to_parts(item, line), line))
    return tuple(found)


def components_of(value: object, where: Where) -> tuple[Component, ...]:
    """Composable node descriptions; one that is not known is kept as such (reported when loaded)."""
    if value is None:
        return ()
    items = value if isinstance(value, (list, tuple)) else [value]
    unknown = [opaque(f"composable node description not known statically ({why(item)})") for item in items
               if not isinstance(item, Component)]
    return tuple(item for item in items if isinstance(item, Component)) + \
        tuple(Component(where=where, pkg=reason, plugin=reason) for reason in unknown)


# -- the API ------------------------------------------------------------------------------
