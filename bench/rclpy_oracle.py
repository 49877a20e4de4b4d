"""The rclpy oracle: run public rclpy programs for real, observe their ports on a live ROS 2 graph,
and score archlog's recovery of a one-node configuration of the same executable, per node, with
ROSDiscover's metric (missed and extra ports as a share of the observed ones).

    python bench/rclpy_oracle.py CHECKOUT... [--domain 32] [--part tuned|held-out|all] [--out PREFIX]

CHECKOUT: folders holding ament_python packages (ros2/demos, ros2/examples, a teleop package, ...);
nothing fetched is part of archlog. Every console_scripts entry point of every package is a program;
one whose module does not import with the installed wheels is skipped (and listed). Each program is
started as a plain process (`--ros-args`) on a private ROS_DOMAIN_ID with discovery on localhost,
with a pseudo-terminal as stdin (keyboard teleops need one); a lifecycle node is driven through
configure and activate; every node of the process is observed for a few seconds (the union of what
was seen), then the process is stopped. archlog analyses the program's package with a ROS 2 launch
file that starts the executable once (ROS_DISTRO=kilted, the wheels' distribution).

Ports compared: (kind, resolved name) of publishers, subscribers, service servers and clients and
actions (the hidden `_action/...` services and topics of an action are its one action port, as
archlog represents it). The built-in ports every node has (models/infrastructure/ros2.yaml
`default`) are scored apart: "own" ports exclude them, "all" includes them.

The held-out part is fixed before any tuning: a program is held out when the first byte of
sha256("package/executable") is divisible by 3 (about a third). Those programs are scored only
at the end, after the fixes made on the tuned part.
Requires the ROS 2 wheels (ros-rclpy, ros-rmw-fastrtps-cpp, message packages) in this interpreter.
"""

from __future__ import annotations

import argparse
import ast
import hashlib
import json
import os
import pty
import subprocess
import sys
import tempfile
import time
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from archlog.analysis import analyse
from archlog.extract.builtin_ports import builtin
from archlog.testgen.processes import stop

KINDS = ("publisher", "subscriber", "service_server", "service_client", "action_server", "action_client")
_ACTION_SERVICES = ("send_goal", "cancel_goal", "get_result")
_ACTION_TOPICS = ("feedback", "status")
OBSERVE_SECONDS = 4.0
START_TIMEOUT = 12.0


def held_out(package: str, executable: str) -> bool:
    """The split, fixed before tuning: about a third of the programs, by a hash of their name."""
    return hashlib.sha256(f"{package}/{executable}".encode()).digest()[0] % 3 == 0


@dataclass
class Program:
    package: str
    executable: str
    folder: Path  # the package folder (its setup.py)
    module: str
    function: str

    @property
    def part(self) -> str:
        return "held-out" if held_out(self.package, self.executable) else "tuned"


Ports = dict[str, dict[tuple[str, str], str]]  # node -> (kind, name) -> type


@dataclass
class Result:
    program: Program
    observed: Ports = field(default_factory=dict)
    recovered: Ports = field(default_factory=dict)
    skipped: str = ""


# -- programs -------------------------------------------------------------------------------------
def programs(checkouts: list[Path]) -> list[Program]:
    """Every console_scripts entry point of the ament_python packages under the checkouts."""
    found = []
    for checkout in checkouts:
        for setup in sorted(checkout.rglob("setup.py")):
            if not (setup.parent / "package.xml").is_file():
                continue
            package = _package_name(setup.parent / "package.xml")
            for entry in _console_scripts(setup):
                name, _, target = entry.partition("=")
                module, _, function = target.strip().partition(":")
                found.append(Program(package, name.strip(), setup.parent, module, function or "main"))
    return found


def _package_name(xml: Path) -> str:
    text = xml.read_text()
    return text.split("<name>", 1)[1].split("</name>", 1)[0].strip()


def _console_scripts(setup: Path) -> list[str]:
    """The console_scripts strings of a setup.py (string constants and module-level names joined with +)."""
    tree = ast.parse(setup.read_text())
    names = {t.id: s.value for s in tree.body if isinstance(s, ast.Assign)
             for t in s.targets if isinstance(t, ast.Name)}

    def text(expr: ast.expr) -> str | None:
        if isinstance(expr, ast.Constant) and isinstance(expr.value, str):
            return expr.value
        if isinstance(expr, ast.Name) and expr.id in names:
            return text(names[expr.id])
        if isinstance(expr, ast.BinOp) and isinstance(expr.op, ast.Add):
            left, right = text(expr.left), text(expr.right)
            return left + right if left is not None and right is not None else None
        if isinstance(expr, ast.JoinedStr):
            parts = [text(v.value) if isinstance(v, ast.FormattedValue) else text(v) for v in expr.values]
            return "".join(p for p in parts if p is not None) if None not in parts else None
        return None

    for node in ast.walk(tree):
        if isinstance(node, ast.Dict):
            for key, value in zip(node.keys, node.values):
                if key is not None and text(key) == "console_scripts" and isinstance(value, (ast.List, ast.Tuple)):
                    return [t for t in (text(e) for e in value.elts) if t]
    return []


def importable(program: Program) -> str:
    """"" when the program's module imports with the installed wheels, else the error."""
    done = subprocess.run([sys.executable, "-c", f"import {program.module}"], cwd=program.folder, env=_env(0),
                          capture_output=True, text=True, timeout=60)
    return "" if done.returncode == 0 else (done.stderr.strip().splitlines() or ["failed"])[-1]


def _env(domain: int) -> dict[str, str]:
    env = dict(os.environ, ROS_DOMAIN_ID=str(domain), ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST",
               PYTHONUNBUFFERED="1")
    env.pop("ROS_STATIC_PEERS", None)
    return env


# -- observation ----------------------------------------------------------------------------------
def observe(program: Program, domain: int) -> Ports:
    """Start the program, drive lifecycle nodes to active, and observe every node it creates."""
    import rclpy

    rclpy.init(domain_id=domain)
    observer = rclpy.create_node("archlog_rclpy_oracle")
    try:
        before = {_full(ns, n) for n, ns in observer.get_node_names_and_namespaces()}
        code = f"import sys; sys.argv[0] = {program.executable!r}; from {program.module} import " \
               f"{program.function} as main; sys.exit(main())"
        primary, secondary = pty.openpty()
        process = subprocess.Popen([sys.executable, "-c", code, "--ros-args"], cwd=program.folder,
                                   env=_env(domain), stdin=secondary, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL, start_new_session=True)
        seen: Ports = {}
        try:
            start = time.monotonic()
            deadline = start + START_TIMEOUT
            first = None
            while time.monotonic() < deadline:
                _poll(observer, before, seen)
                if seen and first is None:
                    first = time.monotonic()
                    deadline = first + OBSERVE_SECONDS
                    _activate(observer, seen)
                if process.poll() is not None and seen:
                    break
                time.sleep(0.4)
            _poll(observer, before, seen)
        finally:
            stop(process, 5.0)
            os.close(primary)
            os.close(secondary)
        return seen
    finally:
        observer.destroy_node()
        rclpy.shutdown()


def _full(namespace: str, name: str) -> str:
    return namespace.rstrip("/") + "/" + name


def _poll(observer, before: set[str], seen: Ports) -> None:
    """Add what the graph shows now for every node not there before."""
    for name, namespace in observer.get_node_names_and_namespaces():
        node = _full(namespace, name)
        if node in before:
            continue
        ports = seen.setdefault(node, {})
        calls = (("publisher", observer.get_publisher_names_and_types_by_node),
                 ("subscriber", observer.get_subscriber_names_and_types_by_node),
                 ("service_server", observer.get_service_names_and_types_by_node),
                 ("service_client", observer.get_client_names_and_types_by_node))
        for kind, call in calls:
            try:
                found = call(name, namespace)
            except Exception:
                continue
            for topic, types in found:
                ports[(kind, topic)] = types[0] if types else ""
    for node, ports in seen.items():
        seen[node] = _fold_actions(ports)


def _fold_actions(ports: dict[tuple[str, str], str]) -> dict[tuple[str, str], str]:
    """An action's hidden services and topics as its one action port."""
    folded: dict[tuple[str, str], str] = {}
    for (kind, name), type_ in ports.items():
        base, _, last = name.rpartition("/_action/")
        if not _ or last not in (*_ACTION_SERVICES, *_ACTION_TOPICS):
            folded[(kind, name)] = type_
        elif last == "send_goal" and kind in ("service_server", "service_client"):
            action = "action_server" if kind == "service_server" else "action_client"
            folded[(action, base)] = type_.removesuffix("_SendGoal")
    return folded


def _activate(observer, seen: Ports) -> None:
    """Configure and activate every lifecycle node seen (its ports made in on_configure then exist)."""
    import rclpy
    from lifecycle_msgs.srv import ChangeState

    for node, ports in seen.items():
        if ("service_server", f"{node}/change_state") not in ports:
            continue
        client = observer.create_client(ChangeState, f"{node}/change_state")
        if client.wait_for_service(timeout_sec=2.0):
            for transition in (1, 3):  # configure, activate
                request = ChangeState.Request()
                request.transition.id = transition
                future = client.call_async(request)
                rclpy.spin_until_future_complete(observer, future, timeout_sec=3.0)
        observer.destroy_client(client)


# -- recovery -------------------------------------------------------------------------------------
def recover(program: Program, scratch: Path) -> Ports:
    """archlog's ports of a one-node configuration of the executable."""
    launch = scratch / f"{program.package}__{program.executable}.launch.xml"
    launch.write_text(f'<launch><node pkg="{program.package}" exec="{program.executable}"/></launch>\n')
    analysis = analyse([program.folder], [str(launch)], {}, [], env={"ROS_DISTRO": "kilted"})
    store = analysis.store
    ports: Ports = {row[0]: {} for row in store.rows("node")}
    for kind in KINDS:
        for _pid, node, name, type_ in store.rows(kind):
            ports.setdefault(node, {})[(kind, store.plain(name))] = str(store.plain(type_))
    return ports


# -- scoring --------------------------------------------------------------------------------------
def is_default_builtin(node: str, key: tuple[str, str]) -> bool:
    """A port every node has (the `default` groups of the built-in table)."""
    table = builtin()
    for group in table.default:
        for kind, name, _type in table.groups[group].ports:
            full = node.rstrip("/") + name[1:] if name.startswith("~") else name
            if (kind, full) == key:
                return True
    return False


def category(node: str, key: tuple[str, str], nodes_missing: bool) -> str:
    """The cause a missed or extra port is counted under."""
    kind, name = key
    last = name.rsplit("/", 1)[-1]
    table = builtin()
    if nodes_missing:
        return "node not recovered"
    for group in table.groups.values():
        if any(k == kind and name == (node.rstrip("/") + n[1:] if n.startswith("~") else n) for k, n, _t in group.ports):
            return f"built-in: {group.name}"
    parameter_services = {n.rsplit("/", 1)[-1] for _k, n, _t in table.groups["parameter_services"].ports}
    if kind == "service_client" and last in parameter_services:
        return "parameter client (AsyncParameterClient)"
    return {"publisher": "topic", "subscriber": "topic", "service_server": "service",
            "service_client": "service", "action_server": "action", "action_client": "action"}[kind]


def score(results: list[Result], own: bool) -> dict:
    """Observed, recovered, missed, extra and type errors, with missed and extra by cause."""
    observed = recovered = 0
    missed: Counter[str] = Counter()
    extra: Counter[str] = Counter()
    types = 0
    rows = []
    for result in results:
        if result.skipped:
            continue
        for node in sorted(result.observed.keys() | result.recovered.keys()):
            seen = {k: t for k, t in result.observed.get(node, {}).items() if not (own and is_default_builtin(node, k))}
            got = {k: t for k, t in result.recovered.get(node, {}).items() if not (own and is_default_builtin(node, k))}
            observed += len(seen)
            recovered += len(got.keys() & seen.keys())
            lost = node not in result.recovered
            for key in seen.keys() - got.keys():
                missed[category(node, key, lost)] += 1
            for key in got.keys() - seen.keys():
                extra["node not observed" if node not in result.observed else category(node, key, False)] += 1
            types += sum(1 for k in seen.keys() & got.keys() if seen[k] and got[k] != seen[k])
            rows.append({"program": f"{result.program.package}/{result.program.executable}", "node": node,
                         "observed": len(seen), "missed": sorted(f"{k} {n}" for k, n in seen.keys() - got.keys()),
                         "extra": sorted(f"{k} {n}" for k, n in got.keys() - seen.keys()),
                         "type_errors": sorted(f"{k} {n}: {got[(k, n)]} vs {seen[(k, n)]}"
                                               for k, n in seen.keys() & got.keys() if seen[(k, n)] and
                                               got[(k, n)] != seen[(k, n)])})
    total_missed, total_extra = sum(missed.values()), sum(extra.values())
    return {"observed": observed, "recovered": recovered, "missed": total_missed, "extra": total_extra,
            "missed_pct": round(100 * total_missed / observed, 1) if observed else 0.0,
            "extra_pct": round(100 * total_extra / observed, 1) if observed else 0.0,
            "type_errors": types, "missed_by_cause": dict(missed.most_common()),
            "extra_by_cause": dict(extra.most_common()), "nodes": rows}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("checkouts", nargs="+", type=Path)
    parser.add_argument("--domain", type=int, default=32)
    parser.add_argument("--part", choices=("tuned", "held-out", "all"), default="tuned")
    parser.add_argument("--out", type=Path, default=None, help="write PREFIX.json")
    parser.add_argument("--only", default="", help="only programs whose package/executable contains this")
    args = parser.parse_args()
    chosen = [p for p in programs(args.checkouts) if (args.part == "all" or p.part == args.part)
              and args.only in f"{p.package}/{p.executable}"]
    results = []
    with tempfile.TemporaryDirectory(prefix="rclpy-oracle-") as scratch:
        for program in chosen:
            result = Result(program)
            result.skipped = importable(program)
            if not result.skipped:
                result.observed = observe(program, args.domain)
                result.recovered = recover(program, Path(scratch))
                if not result.observed:
                    result.skipped = "no node appeared on the graph"
            results.append(result)
            print(f"{program.part:8} {program.package}/{program.executable}: "
                  f"{result.skipped or f'{len(result.observed)} node(s) observed'}", file=sys.stderr)
    report = {"programs": [{"program": f"{r.program.package}/{r.program.executable}", "part": r.program.part,
                            "skipped": r.skipped, "observed": {n: sorted(f"{k} {m} {t}" for (k, m), t in p.items())
                                                               for n, p in r.observed.items()}}
                           for r in results]}
    for part in ("tuned", "held-out"):
        chosen_part = [r for r in results if r.program.part == part]
        if chosen_part:
            report[part] = {"own": score(chosen_part, True), "all": score(chosen_part, False)}
    text = json.dumps(report, indent=1)
    if args.out:
        args.out.with_suffix(".json").write_text(text + "\n")
    for part in ("tuned", "held-out"):
        if part in report:
            for which in ("own", "all"):
                s = report[part][which]
                print(f"{part} {which}: {s['observed']} observed, {s['missed']} missed ({s['missed_pct']}%), "
                      f"{s['extra']} extra ({s['extra_pct']}%), {s['type_errors']} type errors; "
                      f"missed {s['missed_by_cause']} extra {s['extra_by_cause']}")


if __name__ == "__main__":
    main()
