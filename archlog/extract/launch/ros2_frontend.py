"""The XML and YAML frontends of ROS 2 launch (launch_xml, launch_yaml) read into ROS 2 launch actions.

Both dialects share one entity model: an XML element is an entity with string attributes and
child elements; a YAML entity is a mapping whose keys are its attributes, whose list values of
mappings are its sub-entities (`param:`, `remap:`, `arg:`) and whose `children:` list (or the
list itself, for `launch:`) holds its actions, each a one-key mapping `{tag: {...}}`. XML values
are read with YAML rules (`value="5"` is 5) unless a `type` says otherwise; YAML values keep
their YAML type. Unknown tags and attributes, which launch rejects, are reported and skipped.
"""

from __future__ import annotations

import shlex
from collections.abc import Callable
from pathlib import Path

import yaml
from lxml import etree

from archlog import sandbox
from archlog.extract.launch import bounded_yaml
from archlog.extract.launch.model import LaunchError, SubstitutionError
from archlog.extract.launch.read import boolean, open_xml
from archlog.extract.launch.ros2_actions import (
    Action,
    Component,
    Condition,
    DeclareArgument,
    Group,
    Include,
    LoadComponents,
    Node,
    ParamDict,
    ParamFile,
    ParamItem,
    ParamSource,
    ParamText,
    Process,
    PushNamespace,
    Remap,
    SetConfiguration,
    SetEnvironment,
    SetParameter,
    SetParametersFile,
    SetRemap,
    Where,
)
from archlog.extract.launch.ros2_execute import Ros2Launch
from archlog.extract.launch.ros2_subst import Parts, Text, parse, text, yaml_value

_PROCESS = {"cwd", "name", "on_exit", "launch-prefix", "output", "respawn", "respawn_max_retries", "respawn_delay",
            "sigkill_timeout", "sigterm_timeout", "shell", "emulate_tty", "env"}
_NODE = _PROCESS | {"args", "ros_args", "node-name", "exec_name", "pkg", "exec", "namespace", "param", "remap"}
ATTRIBUTES: dict[str, set[str]] = {
    "arg": {"name", "default", "description", "choice"}, "let": {"name", "value"},
    "group": {"scoped", "forwarding", "keep", "children"}, "include": {"file", "arg"},
    "push-ros-namespace": {"namespace"}, "push_ros_namespace": {"namespace"}, "set_remap": {"from", "to"},
    "set_parameter": {"name", "value"}, "set_parameters_from_file": {"filename"}, "set_use_sim_time": {"value"},
    "set_env": {"name", "value"}, "unset_env": {"name"}, "append_env": {"name", "value", "prepend", "separator"},
    "node": _NODE, "node_container": _NODE | {"composable_node"}, "executable": _PROCESS | {"cmd"},
    "load_composable_node": {"target", "composable_node"}, "timer": {"period", "children"},
    "composable_node": {"pkg", "plugin", "name", "namespace", "param", "remap", "extra_arg"},
    "log": {"message", "level"}, "shutdown": {"reason"}, "reset_env": set(), "set_ros_log_dir": {"new_log_dir"},
}
INERT = {"log", "shutdown", "reset_env", "set_ros_log_dir"}  # no effect on the architecture


class Entity:
    """One entity of either frontend: its tag, line, attributes and sub-entities."""

    def __init__(self, tag: str, line: int, attrs: dict[str, object], subs: dict[str, list[Entity]],
                 children: list[Entity] | None) -> None:
        self.tag = tag
        self.line = line
        self.attrs = attrs
        self.subs = subs
        self.children = children

    def get(self, name: str) -> object | None:
        return self.attrs.get(name)

    def required(self, name: str) -> object:
        if name not in self.attrs:
            raise LaunchError(f"<{self.tag}> is missing the required attribute '{name}'")
        return self.attrs[name]

    def sub(self, name: str) -> list[Entity]:
        return self.subs.get(name, [])


# -- XML ----------------------------------------------------------------------------------
def describe_xml(path: Path, launcher: Ros2Launch) -> list[Action] | None:
    """The actions of a ROS 2 XML launch file; None (with a diagnostic) when it cannot be read."""
    root = open_xml(path, launcher.workspace.display(path), launcher.diagnostics, remove_pis=True)
    if root is None:
        return None
    return _Reader(path, launcher, typed=False).actions(_xml_entity(root).children or [])


def _xml_entity(el: etree._Element) -> Entity:
    attrs: dict[str, object] = {}
    for key, value in el.attrib.items():
        if key.endswith("-sep") and key[:-4] in el.attrib:
            continue
        sep = el.get(f"{key}-sep")
        attrs[key] = value.split(sep) if sep else value
    subs: dict[str, list[Entity]] = {}
    children = [_xml_entity(child) for child in el if isinstance(child.tag, str)]
    for child in children:
        subs.setdefault(child.tag, []).append(child)
    return Entity(str(el.tag), el.sourceline or 1, attrs, subs, children)


# -- YAML ---------------------------------------------------------------------------------
class _LineDict(dict):
    """A YAML mapping that knows its line."""

    line = 1


class _LineLoader(bounded_yaml.BoundedLoader):
    """PyYAML's safe loader within the budget; mappings remember where they start."""


def _mapping(loader: yaml.SafeLoader, node: yaml.MappingNode) -> _LineDict:
    loader.flatten_mapping(node)
    result = _LineDict(loader.construct_pairs(node, deep=True))
    result.line = node.start_mark.line + 1
    return result


_LineLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _mapping)


def describe_yaml(path: Path, launcher: Ros2Launch) -> list[Action] | None:
    """The actions of a ROS 2 YAML launch file; None (with a diagnostic) when it cannot be read."""
    shown = launcher.workspace.display(path)
    try:
        loader = _LineLoader(sandbox.read_text(path, "launch"))
        with bounded_yaml.crossing_in(loader, shown):
            data = loader.get_single_data()
        loader.dispose()
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        launcher.diagnostics.add(shown, mark.line + 1 if mark else 1, "launch-yaml", f"malformed launch YAML: {exc}",
                                 "error")
        return None
    except sandbox.Refused as exc:
        launcher.diagnostics.add(shown, 1, exc.code, f"cannot read launch file: {exc}", "error")
        return None
    if not isinstance(data, dict) or list(data) != ["launch"]:
        launcher.diagnostics.add(shown, 1, "launch-yaml", "not a ROS 2 YAML launch file: the root must be the one key "
                                 "'launch'", "error")
        return None
    reader = _Reader(path, launcher, typed=True)
    return reader.actions(reader.yaml_children(data["launch"], "launch", getattr(data, "line", 1)))


class _Reader:
    """Reads the entities of one file into actions, reporting what launch would reject."""

    def __init__(self, path: Path, launcher: Ros2Launch, typed: bool) -> None:
        self.path = path
        self.launcher = launcher
        self.typed = typed  # YAML values keep their type; XML text is read with YAML rules

    def where(self, line: int) -> Where:
        return Where(self.path, line)

    def problem(self, line: int, code: str, message: str, severity: str = "error") -> None:
        self.launcher.diag(self.where(line), code, message, severity)

    # -- YAML entities --------------------------------------------------------------------
    def yaml_entity(self, tag: str, body: object, line: int) -> Entity:
        """A YAML entity `{tag: body}`: a mapping of attributes, or a list of children."""
        if isinstance(body, list):
            return Entity(tag, line, {}, {}, self.yaml_children(body, tag, line))
        if not isinstance(body, dict):
            raise LaunchError(f"'{tag}' must be a mapping of attributes, not {type(body).__name__}")
        line = getattr(body, "line", line)
        attrs: dict[str, object] = {}
        subs: dict[str, list[Entity]] = {}
        children = None
        for key, value in body.items():
            key = str(key)
            if key == "children" and isinstance(value, list):
                children = self.yaml_children(value, tag, line)
            elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
                subs[key] = [self.yaml_entity(key, v, line) for v in value]
            else:
                attrs[key] = value
        return Entity(tag, line, attrs, subs, children)

    def yaml_children(self, items: object, parent: str, line: int) -> list[Entity]:
        if not isinstance(items, list):
            self.problem(line, "launch-yaml", f"the children of '{parent}' must be a list of entities")
            return []
        found = []
        for item in items:
            item_line = getattr(item, "line", line)
            if not isinstance(item, dict) or len(item) != 1:
                self.problem(item_line, "launch-yaml", "an entity must be a mapping with one key, its type")
                continue
            (tag, body), = item.items()
            try:
                found.append(self.yaml_entity(str(tag), body, item_line))
            except LaunchError as exc:
                self.problem(item_line, "launch-yaml", str(exc))
        return found

    # -- actions --------------------------------------------------------------------------
    def actions(self, entities: list[Entity]) -> list[Action]:
        found = []
        for entity in entities:
            handler: Callable[[Entity, Where, tuple[Condition, ...]], Action | None] | None = \
                getattr(self, "_" + entity.tag.replace("-", "_"), None)
            if handler is None or entity.tag not in ATTRIBUTES:
                self.problem(entity.line, "launch-tag", f"unrecognized tag <{entity.tag}> ignored", "warning")
                continue
            extra = set(entity.attrs) - ATTRIBUTES[entity.tag] - {"if", "unless"}
            if entity.tag not in ("group", "timer"):  # their sub-entities are actions
                extra |= set(entity.subs) - ATTRIBUTES[entity.tag]
            for name in sorted(extra):
                self.problem(entity.line, "launch-attr", f"unknown <{entity.tag}> attribute '{name}' ignored",
                             "warning")
            try:
                action = handler(entity, self.where(entity.line), self.conditions(entity))
            except (SubstitutionError, LaunchError) as exc:
                self.problem(entity.line, "launch-invalid", f"<{entity.tag}>: {exc}")
                continue
            if action is not None:
                found.append(action)
        return found

    def conditions(self, entity: Entity) -> tuple[Condition, ...]:
        if entity.get("if") is not None and entity.get("unless") is not None:
            raise LaunchError("if and unless conditions can't be used simultaneously")
        for kind in ("if", "unless"):
            if entity.get(kind) is not None:
                return (Condition(kind, self.parts(entity.get(kind))),)
        return ()

    @staticmethod
    def parts(value: object) -> Parts:
        """An attribute read as substitutions (YAML scalars are written as launch's str() would)."""
        if isinstance(value, bool):
            return text(str(value).lower())
        if isinstance(value, list):
            raise LaunchError(f"expected a single value, not a list: {value}")
        return parse(str(value))

    def optional(self, entity: Entity, name: str) -> Parts | None:
        value = entity.get(name)
        return None if value is None else self.parts(value)

    def flag(self, entity: Entity, name: str, default: bool) -> bool:
        value = entity.get(name)
        if value is None:
            return default
        if isinstance(value, bool):
            return value
        flag = boolean(str(value), numeric=False)
        if flag is not None:
            return flag
        raise LaunchError(f"'{name}' must be true or false, not {value!r}")

    def _arg(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        choices = tuple(str(c.required("value")) for c in e.sub("choice")) if e.sub("choice") else None
        return DeclareArgument(where=where, conditions=conds, name=str(e.required("name")),
                               default=self.optional(e, "default"), choices=choices)

    def _let(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return SetConfiguration(where=where, conditions=conds, name=self.parts(e.required("name")),
                                value=self.parts(e.required("value")))

    def _group(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        keep = tuple((self.parts(k.required("name")), self.parts(k.required("value"))) for k in e.sub("keep"))
        children = [c for c in e.children or [] if c.tag != "keep"]
        return Group(where=where, conditions=conds, actions=tuple(self.actions(children)),
                     scoped=self.flag(e, "scoped", True), forwarding=self.flag(e, "forwarding", True), keep=keep)

    def _timer(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return Group(where=where, conditions=conds, actions=tuple(self.actions(e.children or [])), scoped=False)

    def _include(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        args = tuple((self.parts(a.required("name")), self.parts(a.required("value"))) for a in e.sub("arg"))
        return Include(where=where, conditions=conds, target=self.parts(e.required("file")), args=args)

    def _push_ros_namespace(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return PushNamespace(where=where, conditions=conds, namespace=self.parts(e.required("namespace")))

    def _set_remap(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return SetRemap(where=where, conditions=conds, src=self.parts(e.required("from")),
                        dst=self.parts(e.required("to")))

    def _set_parameter(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        value = e.required("value")
        return SetParameter(where=where, conditions=conds, name=self.parts(e.required("name")),
                            value=self.param_value(value, None) if not isinstance(value, str)
                            else ParamText(self.parts(value)))

    def _set_parameters_from_file(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return SetParametersFile(where=where, conditions=conds, path=self.parts(e.required("filename")))

    def _set_use_sim_time(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return SetParameter(where=where, conditions=conds, name=text("use_sim_time"),
                            value=ParamText(self.parts(e.required("value")), "bool"))

    def _set_env(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return SetEnvironment(where=where, conditions=conds, name=self.parts(e.required("name")),
                              value=self.parts(e.required("value")))

    def _unset_env(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return SetEnvironment(where=where, conditions=conds, name=self.parts(e.required("name")), value=None)

    def _append_env(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return SetEnvironment(where=where, conditions=conds, name=self.parts(e.required("name")),
                              value=self.parts(e.required("value")),
                              append="prepend" if self.flag(e, "prepend", False) else "append",
                              separator=self.optional(e, "separator") or text(":"))

    def _executable(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return Process(where=where, conditions=conds, cmd=(self.parts(e.required("cmd")),))

    def _node(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        arguments = self.optional(e, "args")
        ros_arguments = self.optional(e, "ros_args")
        return Node(where=where, conditions=conds, pkg=self.optional(e, "pkg"), exe=self.parts(e.required("exec")),
                    name=self.optional(e, "name"), namespace=self.optional(e, "namespace"),
                    params=self.params(e.sub("param")), remaps=self.remaps(e.sub("remap")),
                    arguments=_command_line(arguments) if arguments is not None else (),
                    ros_arguments=_command_line(ros_arguments) if ros_arguments is not None else None,
                    components=self.components(e.sub("composable_node")))

    _node_container = _node

    def _load_composable_node(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> Action:
        return LoadComponents(where=where, conditions=conds, target=self.parts(e.required("target")),
                              components=self.components(e.sub("composable_node")))

    def _inert(self, e: Entity, where: Where, conds: tuple[Condition, ...]) -> None:
        """Tags with no effect on the architecture (log, shutdown...)."""

    _log = _shutdown = _reset_env = _set_ros_log_dir = _inert

    def components(self, entities: list[Entity]) -> tuple[Component, ...]:
        found = []
        for e in entities:
            extra = set(e.attrs) - ATTRIBUTES["composable_node"] - {"if", "unless"}
            for name in sorted(extra):
                self.problem(e.line, "launch-attr", f"unknown <composable_node> attribute '{name}' ignored", "warning")
            found.append(Component(where=self.where(e.line), conditions=self.conditions(e),
                                   pkg=self.parts(e.required("pkg")), plugin=self.parts(e.required("plugin")),
                                   name=self.parts(e.required("name")), namespace=self.optional(e, "namespace"),
                                   params=self.params(e.sub("param")), remaps=self.remaps(e.sub("remap"))))
        return tuple(found)

    def remaps(self, entities: list[Entity]) -> tuple[Remap, ...]:
        return tuple(Remap(self.parts(r.required("from")), self.parts(r.required("to")), r.line) for r in entities)

    def params(self, entities: list[Entity]) -> tuple[ParamSource, ...]:
        """A node's <param>s: files (`from`) and values, nested ones named a.b."""
        found: list[ParamSource] = []
        for p in entities:
            source, name = p.get("from"), p.get("name")
            if source is not None and name is not None:
                raise LaunchError("<param>: name and from attributes are mutually exclusive")
            if source is not None:
                allow = p.get("allow_substs")
                found.append(ParamFile(self.parts(source), p.line, False if allow is None else
                                       (allow if isinstance(allow, bool) else self.parts(allow))))
            elif name is not None:
                found.append(ParamDict(tuple(self.param_items(p, ()))))
            else:
                raise LaunchError("<param> needs a name or from attribute")
        return tuple(found)

    def param_items(self, p: Entity, prefix: Parts) -> list[ParamItem]:
        name = self.parts(p.required("name"))
        full = (*prefix, Text("."), *name) if prefix else name
        nested, value, kind = p.sub("param"), p.get("value"), p.get("type")
        if nested and (value is not None or kind is not None):
            raise LaunchError("<param>: nested parameters exclude the value and type attributes")
        if nested:
            return [item for child in nested for item in self.param_items(child, full)]
        if value is None:
            raise LaunchError("<param> needs a value attribute or nested params")
        return [ParamItem(full, self.param_value(value, None if kind in (None, "yaml") else str(kind)), p.line)]

    def param_value(self, value: object, kind: str | None) -> object:
        """A <param> value: XML text is read with YAML rules (or as `kind`), YAML keeps its type;
        text with substitutions is performed at launch."""
        if isinstance(value, list):
            return [self.param_value(v, kind[8:] if kind and kind.startswith("list_of_") else kind) for v in value]
        if not isinstance(value, str):
            return value
        if kind is None and not self.typed:
            loaded = yaml_value(value)
            if not isinstance(loaded, (str, dict)):
                return loaded
            value = loaded if isinstance(loaded, str) else value
        parts = parse(value)
        if len(parts) == 1 and isinstance(parts[0], Text) and kind in (None, "str"):
            return parts[0].text
        return ParamText(parts, kind)


def _command_line(parts: Parts) -> tuple[Parts, ...]:
    """An `args` attribute split into words as launch splits a command line: literal text at the
    spaces, a substitution staying inside the word it is written in."""
    words: list[list] = [[]]
    for part in parts:
        if not isinstance(part, Text):
            words[-1].append(part)
            continue
        chunk = part.text
        if chunk[:1].isspace() and words[-1]:
            words.append([])
        try:
            pieces = shlex.split(chunk)
        except ValueError as exc:
            raise LaunchError(f"arguments cannot be split into words ({exc}): {chunk}") from None
        for index, piece in enumerate(pieces):
            if index:
                words.append([])
            words[-1].append(Text(piece))
        if chunk[-1:].isspace() and words[-1]:
            words.append([])
    return tuple(tuple(w) for w in words if w)
