"""ros_control controllers started by `controller_manager spawner NAME...`, as node instances.

A controller is a plugin loaded into the hardware node's controller_manager, not a node; its type
comes from the parameter `<namespace>/<NAME>/type` (e.g. diff_drive_controller/DiffDriveController)
and its topics live under `<namespace>/<NAME>`. Each one becomes an instance of the model for
(package, class) named `<namespace>/<NAME>` beside the spawner, so its ports take part in the rules.
"""

from __future__ import annotations

import shlex

from archlog import names
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import LaunchConfig, LaunchNode
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
        for name in controllers:
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
