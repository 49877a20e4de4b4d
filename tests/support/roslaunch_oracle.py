"""Run under Debian's /usr/bin/python3: load launch files with roslaunch's own config loader
(nothing is started) and print the configuration as JSON.

Input (stdin): {"files": [...], "args": {"name": "value"}}. Output: {"nodes": [...],
"params": {...}, "error": null | "message"}. Used by tests/test_launch_differential.py.
"""

import json
import sys
import xmlrpc.client


def plain(value):
    if isinstance(value, xmlrpc.client.Binary):
        return {"binary": len(value.data)}
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    return value


def main():
    request = json.load(sys.stdin)
    sys.argv = ["roslaunch"] + ["{}:={}".format(*kv) for kv in request["args"].items()]
    import roslaunch.config
    import roslaunch.loader
    import roslaunch.xmlloader

    # never run a project's commands: a command= param gets a placeholder value
    original = roslaunch.loader.Loader.param_value

    def param_value(self, verbose, name, ptype, value, textfile, binfile, command):
        if command is not None:
            return "<command not run>"
        return original(self, verbose, name, ptype, value, textfile, binfile, command)

    roslaunch.loader.Loader.param_value = param_value

    result = {"nodes": [], "params": {}, "error": None}
    try:
        config = roslaunch.config.load_config_default(request["files"], None, verbose=False,
                                                      loader=roslaunch.xmlloader.XmlLoader())
    except Exception as exc:  # roslaunch raises many types; all mean "rejected"
        result["error"] = f"{type(exc).__name__}: {exc}"
        print(json.dumps(result))
        return
    for node in config.nodes + config.tests:
        if node.package == "rosout":
            continue
        result["nodes"].append({"name": node.name, "namespace": node.namespace, "package": node.package,
                                "type": node.type, "args": node.args, "remaps": [list(r) for r in node.remap_args]})
    for key, param in config.params.items():
        if key not in ("/rosversion", "/rosdistro", "/run_id"):
            result["params"][key] = plain(param.value)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
