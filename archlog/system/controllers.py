"""ros_control controllers started by `controller_manager spawner NAME...`, as node instances.

A controller is a plugin loaded into the hardware node's controller_manager, not a node; its type
comes from the parameter `<namespace>/<NAME>/type` (e.g. diff_drive_controller/DiffDriveController)
and its topics live under `<namespace>/<NAME>`. Each one becomes an instance of the model for
(package, class) named `<namespace>/<NAME>` beside the spawner, so its ports take part in the rules.

A word naming a .yaml/.yml file is loaded as the spawner does (`rosparam.set_param("", file)`): its
keys become parameters under the spawner's namespace, and each top-level key whose value sets
`type` is spawned as a controller.

ROS 2 (ros2_control): each controller named on the spawner's command line is a node named after
it in the namespace of the controller manager (`-c/--controller-manager`, default
`controller_manager`), hosted by that process. `-p/--param-file FILE` gives the controllers their
parameters (the file's `NAME: ros__parameters:` entries whose node key matches the controller,
as a node's parameter file does); the type is `-t/--controller-type`, else the file's `type`, else
the controller manager's parameter `NAME.type`. A ROS 2 controller's model is keyed by its C++
class (`diff_drive_controller::DiffDriveController`), as a component's is, apart from ROS 1's.
"""

from __future__ import annotations

import shlex
from pathlib import Path

import yaml

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch import bounded_yaml
from archlog.extract.launch.model import Element, LaunchConfig, LaunchNode, RefusedRead, read_file
from archlog.extract.launch.ros2_params import Entry, load_param_file, matches
from archlog.system.command_line import split_options

VALUED = {"--namespace", "--wait-for", "--timeout", "--shutdown-timeout"}
# the ROS 2 spawner's options that take a value (controller_manager/spawner.py, humble to jazzy)
_SHORT = {"-c": "--controller-manager", "-p": "--param-file", "-n": "--namespace", "-t": "--controller-type"}
VALUED_ROS2 = {*_SHORT, *_SHORT.values(), "--controller-manager-timeout", "--switch-timeout",
               "--service-call-timeout", "--controller-ros-args"}


def controller_nodes(config: LaunchConfig, diagnostics: DiagnosticSink) -> list[LaunchNode]:
    """One instance per controller each spawner starts (`--namespace NS` moves them)."""
    found = []
    for spawner in (n for n in config.nodes if (n.pkg, n.type) == ("controller_manager", "spawner")):
        if spawner.ros2:
            found += _ros2_controllers(spawner, config, diagnostics)
            continue
        words = shlex.split(spawner.args)  # the launch interpreter has rejected args that do not split
        controllers, options = split_options(words, VALUED)
        namespace = names.resolve(options["--namespace"], spawner.namespace, spawner.name) \
            if "--namespace" in options else spawner.namespace
        for name in [n for word in controllers for n in _expand(word, config, spawner, diagnostics)]:
            instance = names.resolve(name, namespace, spawner.name)
            value = config.params.get(names.canonical(instance + "/type"), (None,))[0]
            if not isinstance(value, str) or "/" not in value:
                diagnostics.add(spawner.elem.file, spawner.elem.line, "controller-type",
                                f"spawner starts {instance}, but {instance}/type is not set to PKG/Class "
                                "in this configuration; its topics are unknown", "warning")
                continue
            pkg, cls = value.split("/", 1)
            found.append(LaunchNode(spawner.elem, pkg, cls, instance, namespace, chain=spawner.chain))
    return found


def _ros2_controllers(spawner: LaunchNode, config: LaunchConfig, diagnostics: DiagnosticSink) -> list[LaunchNode]:
    """The controllers a ROS 2 spawner loads, with the parameters its --param-file gives them. A
    spawner the launch file does not name calls itself spawner_<its first controller>."""
    controllers, options = split_options(shlex.split(spawner.args), VALUED_ROS2)
    if not spawner.declared and controllers:
        spawner.name = names.join(spawner.namespace, f"spawner_{controllers[0]}")
    option = {long: options.get(long, options.get(short)) for short, long in _SHORT.items()}
    namespace = names.resolve(option["--namespace"], spawner.namespace, spawner.name) \
        if option["--namespace"] else spawner.namespace
    manager = names.resolve(option["--controller-manager"] or "controller_manager", namespace, spawner.name)
    entries = _param_file(option["--param-file"], spawner, diagnostics) if option["--param-file"] else []
    found = []
    for name in controllers:
        instance = names.join(names.namespace_of(manager), name)
        given = {dotted: value for pattern, dotted, value, _line in entries
                 if matches(pattern, instance) or pattern.strip("/") == name}
        for dotted, value in given.items():
            config.params[f"{instance}/{dotted}"] = (value, spawner.elem)
        type_ = option["--controller-type"] or given.get("type") or \
            config.params.get(f"{manager}/{name}.type", (None,))[0]
        if not isinstance(type_, str) or "/" not in type_:
            diagnostics.add(spawner.elem.file, spawner.elem.line, "controller-type",
                            f"spawner loads {instance} into {manager}, but its type (PKG/Class) is not given: "
                            f"not by -t, its parameter file or {manager}'s parameter {name}.type; its topics are "
                            "unknown", "warning")
            continue
        pkg, cls = type_.split("/", 1)
        found.append(LaunchNode(spawner.elem, pkg, f"{pkg}::{cls}", instance, names.namespace_of(instance),
                                chain=spawner.chain, ros2=True))
    return found


def _param_file(path: str, spawner: LaunchNode, diagnostics: DiagnosticSink) -> list[Entry]:
    """The entries of a ROS 2 spawner's --param-file (problems are diagnostics in the file, or at
    the spawner when it is not read)."""
    try:
        text = read_file(path, "params")
    except RefusedRead as exc:
        diagnostics.add(spawner.elem.file, spawner.elem.line, exc.code, f"spawner's parameter file not read: {exc}")
        return []
    return load_param_file(Path(path), path, diagnostics, text)


def _expand(word: str, config: LaunchConfig, spawner: LaunchNode, diagnostics: DiagnosticSink) -> list[str]:
    """The controllers a spawner's word names: itself, or a YAML file's configured controllers
    (whose parameters are loaded under the spawner's namespace)."""
    if not word.endswith((".yaml", ".yml")):
        return [word]
    where = spawner.elem
    try:
        data = bounded_yaml.load(read_file(word, "params"))
    except RefusedRead as exc:
        diagnostics.add(where.file, where.line, exc.code, f"spawner's parameter file not read: {exc}")
        return []
    except yaml.YAMLError as exc:  # a crossed budget goes up, as for <rosparam>
        diagnostics.add(where.file, where.line, "param-file", f"spawner's parameter file {word} is not "
                        f"valid YAML: {(str(exc).splitlines() or [type(exc).__name__])[0]}")
        return []
    if not isinstance(data, dict):
        diagnostics.add(where.file, where.line, "param-file",
                        f"spawner's parameter file {word} is not a dictionary; no controller is spawned from it")
        return []
    _put_tree(config, spawner.namespace, data, where)
    return [key for key, value in data.items() if isinstance(key, str) and isinstance(value, dict) and "type" in value]


def _put_tree(config: LaunchConfig, key: str, value: object, elem: Element) -> None:
    """rosparam's loading: a dict becomes one parameter per leaf."""
    if isinstance(value, dict):
        for k, v in value.items():
            if isinstance(k, str):
                _put_tree(config, names.join(key, k), v, elem)
        return
    config.params[names.canonical(key)] = (value, elem)
