"""Compare archlog's launch interpretation with roslaunch's for the same files and args."""

from __future__ import annotations

import json
import os
import re
import shlex
import socket
import subprocess
from dataclasses import dataclass
from pathlib import Path

from archlog import names, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.ros1 import LaunchInterpreter
from archlog.extract.launch.ros1_subst import auto_value
from archlog.extract.workspace.index import Workspace
from archlog.sandbox import Sandbox
from archlog.values import Unknown

ORACLE = Path(__file__).with_name("roslaunch_oracle.py")
_HOST = re.sub(r"[.\-:]", "_", socket.gethostname())
_ROSLAUNCH_ANON = re.compile(rf"(\w+?)_{re.escape(_HOST)}_\d+_\d+")
_ARCHLOG_ANON = re.compile(r"(\w+?)_anon\d+")


@dataclass
class View:
    """What both sides must agree on: nodes with their effective remaps, and parameter values."""

    nodes: dict[str, dict]
    params: dict[str, object]
    error: str | None
    diagnostics: list = None


def oracle_env(package_path: list[Path]) -> dict[str, str]:
    """The environment roslaunch runs in; archlog is given the same one explicitly."""
    env = {**os.environ, "ROS_PACKAGE_PATH": os.pathsep.join(map(str, package_path)),
           "PATH": "/usr/bin:" + os.environ.get("PATH", ""), "ROS_HOME": "/tmp/archlog-oracle-home"}
    env.pop("PYTHONPATH", None)
    return env


def roslaunch_view(files: list[Path], args: dict[str, str], package_path: list[Path]) -> View:
    out = subprocess.run(["/usr/bin/python3", str(ORACLE)], input=json.dumps({"files": list(map(str, files)),
                         "args": args}), capture_output=True, text=True, env=oracle_env(package_path), timeout=60,
                         check=False)
    if out.returncode != 0:
        raise RuntimeError(f"oracle failed: {out.stderr[-2000:]}")
    data = json.loads(out.stdout.strip().splitlines()[-1])
    # command= params are never run (archlog records them as unknown): leave them out
    nodes, params = {}, {k: _anon(v) for k, v in data["params"].items() if v != "<command not run>"}
    for node in data["nodes"]:
        ns, name, remaps = node["namespace"], node["name"], [tuple(r) for r in node["remaps"]]
        for word in shlex.split(node["args"] or ""):
            key, sep, value = word.partition(":=")
            if not sep:
                continue
            if key == "__name":
                name = value
            elif key == "__ns":
                ns = names.join("/", value)
            elif key.startswith("_") and not key.startswith("__"):
                params[names.join(names.join(ns, name), key[1:])] = auto_value(value)
            elif not key.startswith("__"):
                remaps = [r for r in remaps if r[0] != key] + [(key, value)]
        full = _anon(names.join(ns, name))
        nodes[full] = {"pkg": node["package"], "type": node["type"], "namespace": names.canonical(ns) or "/",
                       "remaps": {_anon(a): _anon(b) for a, b in remaps}}
    return View(nodes, {_anon(k): v for k, v in params.items()}, data["error"])


def archlog_view(files: list[Path], args: dict[str, str], package_path: list[Path]) -> View:
    sink = DiagnosticSink()
    with sandbox.active(Sandbox(None, oracle_env(package_path))):
        config = LaunchInterpreter(Workspace(package_path, sink), sink).load(files, args)
    nodes = {}
    for node in config.nodes:
        nodes[_anon(node.name)] = {"pkg": node.pkg, "type": node.type, "namespace": node.namespace,
                                   "remaps": {_anon(a): _anon(b) for a, b, _e in node.remaps}}
    params = {_anon(k): _anon(v) for k, (v, _e) in config.params.items() if not isinstance(v, Unknown)}
    errors = [d for d in sink.items if d.severity == "error" or d.code in ("launch-unresolved", "launch-condition")]
    # roslaunch rejects nodes declared with one name; when they also keep it, AL301 reports it
    declared = [n.declared for n in config.nodes if n.declared]
    duplicates = len(declared) != len(set(declared))
    return View(nodes, params, "duplicate node names" if duplicates and not errors else
                (errors[0].message if errors else None), sink.items)


def _anon(value: object) -> object:
    if isinstance(value, str):
        return _ARCHLOG_ANON.sub(r"\1_ANON", _ROSLAUNCH_ANON.sub(r"\1_ANON", value))
    return value


def case_args(main: Path) -> dict[str, str]:
    """Args written in the main file as a comment: <!-- args: a:=1 b:=two -->."""
    match = re.search(r"<!--\s*args:(.*?)-->", main.read_text())
    return dict(w.split(":=", 1) for w in shlex.split(match.group(1))) if match else {}


def expected_error_lines(files: list[Path]) -> list[tuple[str, int]]:
    """Elements marked with <!-- roslaunch-error --> on the line above them."""
    marks = []
    for path in files:
        lines = path.read_text().splitlines()
        marks += [(path.name, i + 2) for i, line in enumerate(lines) if "<!-- roslaunch-error -->" in line]
    return marks
