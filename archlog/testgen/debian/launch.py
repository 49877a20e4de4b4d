"""Start the nodes of a ROS 1 configuration with Debian's roslaunch, again and again (run under
/usr/bin/python3; never imported by archlog).

    launch.py SPEC.json

SPEC: {"files": [launch files], "args": {name: value}, "nodes": [resolved names] or null (all),
"coverage": {resolved name: [data file, source folder, script]}: Python nodes run under coverage.py
(when roslaunch finds that script as the node's executable)}.
The launch files are read once with roslaunch's own loader; then, for every line
{"params": {resolved name: value}} on stdin, the configuration's parameters and these (which win)
are set on the master and the kept nodes are started (the caller kills them before the next line).
Writes "N PID..." (the started processes) to SPEC.json.done when the Nth start is done; stops everything when stdin closes.
"""

import contextlib
import json
import os
import signal
import sys

import rosgraph
import rosgraph.names
import roslaunch.config
import roslaunch.scriptapi
import roslib.packages


def main(spec_path):
    with open(spec_path) as f:
        spec = json.load(f)
    argv = [f"{k}:={v}" for k, v in spec["args"].items()]
    config = roslaunch.config.load_config_default([(f, argv) for f in spec["files"]], None)
    keep = set(spec["nodes"]) if spec["nodes"] is not None else None
    nodes = [n for n in config.nodes
             if keep is None or rosgraph.names.ns_join(n.namespace, n.name) in keep]
    for node in nodes:
        measured = spec.get("coverage", {}).get(rosgraph.names.ns_join(node.namespace, node.name))
        found = roslib.packages.find_node(node.package, node.type) if measured else None
        if measured and found and os.path.realpath(found[0]) == os.path.realpath(measured[2]):
            # its data file is written when it ends (SIGINT); a prefix of its own (nice, ...) comes first
            prefix = f"{sys.executable} -m coverage run --parallel-mode --data-file={measured[0]} --source={measured[1]}"
            node.launch_prefix = f"{node.launch_prefix or ''} {prefix}".strip()
    master = rosgraph.Master("/archlog_testgen_launcher")
    launcher = roslaunch.scriptapi.ROSLaunch()
    launcher.start()
    started: list = []
    for number, line in enumerate(sys.stdin, 1):
        for proc in started:  # the caller killed them; make sure
            if proc.pid > 0:
                with contextlib.suppress(OSError):
                    os.kill(proc.pid, signal.SIGKILL)
        params = {name: p.value for name, p in config.params.items()}
        params.update(json.loads(line)["params"])
        for name, value in params.items():
            master.setParam(name, value)
        for node in nodes:
            node.output = "screen"
        started = [launcher.launch(node) for node in nodes]
        with open(spec_path + ".done", "w") as done:
            done.write(" ".join(map(str, [number] + [proc.pid for proc in started])))
    launcher.stop()


if __name__ == "__main__":
    main(sys.argv[1])
