"""ros_control controllers started by `controller_manager spawner NAME...`, as node instances.

A controller is a plugin loaded into the hardware node's controller_manager, not a node; its type
comes from the parameter `<namespace>/<NAME>/type` (e.g. diff_drive_controller/DiffDriveController)
and its topics live under `<namespace>/<NAME>`. Each one becomes an instance of the model for
(package, class) named `<namespace>/<NAME>` beside the spawner, so its ports take part in the rules.

A word naming a .yaml/.yml file is loaded as the spawner does (`rosparam.set_param("", file)`): its
keys become parameters under the spawner's namespace, and each top-level key whose value sets
`type` is spawned as a controller.
"""

from __future__ import annotations

import shlex

import yaml

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch import bounded_yaml
from archlog.extract.launch.model import Element, LaunchConfig, LaunchNode, RefusedRead, read_file
from archlog.system.command_line import split_options

VALUED = {"--namespace", "--wait-for", "--timeout", "--shutdown-timeout"}


def controller_nodes(config: LaunchConfig, diagnostics: DiagnosticSink) -> list[LaunchNode]:
    """One instance per controller each spawner starts (`--namespace NS` moves them)."""
    found = []
    for spawner in (n for n in config.nodes if (n.pkg, n.type) == ("controller_manager", "spawner")):
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
