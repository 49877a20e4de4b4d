"""Survey: run archlog's whole pipeline on real ROS 2 repositories, to find crashes and false positives.

    python bench/ros2_survey.py ROOT... [--timeout S] [--json FILE] [--show N] [--findings]
                                [--config 'LAUNCH [name:=value ...]']... [--rosrun-only]

Each ROOT is one repository, indexed as the workspace. It is checked once per ROS 2 launch file
in it (`*.launch.py`, `*_launch.py` and the same for xml and yaml, `launch/*.py`), and once without a launch
file (the rosrun configuration: every executable once). `--config` replaces the launch files by
the ones given (relative to ROOT, each with its launch arguments; repeat it); `--rosrun-only`
checks only the rosrun configuration. Each run is `analyse` plus the built-in rules, as `archlog check`
does, in a child process with a time limit; any exception is a crash, with its traceback.
Per repository: launch files, crashes (must be 0), timeouts, nodes and ports recovered, ports
with a known QoS and the publisher/subscriber pairs the QoS rules can judge, diagnostics by code,
findings by rule, seconds. `--findings` lists each distinct finding; `--json` writes every run
(diagnostics, findings, tracebacks).
"""

from __future__ import annotations

import argparse
import collections
import contextlib
import json
import multiprocessing
import os
import signal
import sys
import time
import traceback
from dataclasses import asdict, dataclass, field
from multiprocessing.connection import Connection
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from archlog.analysis import analyse  # noqa: E402
from archlog.extract.workspace.packages import SKIP_DIRS  # noqa: E402
from archlog.rules.engine import Engine, render  # noqa: E402
from archlog.rules.ruleset import load_rules  # noqa: E402

PORTS = ("publisher", "subscriber", "service_server", "service_client", "action_server", "action_client")
ROSRUN = "(rosrun)"


@dataclass
class Run:
    """One configuration of one repository: a launch file, or ROSRUN."""

    root: str
    launch: str
    args: dict[str, str] = field(default_factory=dict)
    seconds: float = 0.0
    crash: str | None = None  # the traceback
    timeout: bool = False
    nodes: int = 0
    ports: int = 0
    qos_ports: int = 0  # ports whose QoS reliability is known
    qos_pairs: int = 0  # publisher/subscriber pairs of one topic that both know it (prelude's qos_pair)
    diagnostics: dict[str, int] = field(default_factory=dict)
    messages: list[str] = field(default_factory=list)  # every diagnostic, for the JSON
    findings: list[dict] = field(default_factory=list)


def launch_files(root: Path) -> list[Path]:
    """The ROS 2 launch files under root, by name (build and hidden folders skipped)."""
    found = []
    for path in sorted(root.rglob("*")):
        parts = path.relative_to(root).parts
        if not path.is_file() or any(p in SKIP_DIRS or p.startswith(".") for p in parts):
            continue
        name = path.name
        if name.endswith((".launch.py", ".launch.xml", ".launch.yaml", "_launch.py", "_launch.xml", "_launch.yaml")) or \
                (path.suffix == ".py" and path.parent.name == "launch" and name != "__init__.py"):
            found.append(path)
    return found


def check(root: Path, launch: Path | None, args: dict[str, str]) -> Run:
    """archlog check ROOT [--launch LAUNCH name:=value...] in this process: facts, then the built-in rules."""
    run = Run(str(root), label(root, launch, args), args)
    start = time.perf_counter()
    try:
        analysis = analyse([root], [str(launch)] if launch else [], args, [])
        ctl, findings = Engine(load_rules([])).run(analysis.store)
    except Exception:  # the point of the survey: any exception is a crash to report
        run.crash = traceback.format_exc()
    else:
        store = analysis.store
        run.nodes = len(store.rows("node"))
        run.ports = sum(len(store.rows(kind)) for kind in PORTS)
        run.qos_ports = sum(1 for row in store.rows("qos") if row[1] == "reliability")
        run.qos_pairs = sum(1 for _ in ctl.symbolic_atoms.by_signature("qos_pair", 5))
        run.diagnostics = dict(collections.Counter(d.code for d in analysis.diagnostics.items))
        run.messages = [str(d) for d in analysis.diagnostics.items]
        run.findings = [{"rule": f.rule.id, "file": f.location.file, "line": f.location.line,
                         "message": f.message, "related": [f"{r.file}:{r.line}" for r in f.related],
                         "values": {k: render(v) for k, v in f.values.items()}} for f in findings]
    run.seconds = round(time.perf_counter() - start, 2)
    return run


def label(root: Path, launch: Path | None, args: dict[str, str]) -> str:
    """How a configuration is named in the output: the launch file and its arguments, or ROSRUN."""
    if launch is None:
        return ROSRUN
    return " ".join([str(launch.relative_to(root)), *(f"{k}:={v}" for k, v in args.items())])


def configurations(root: Path, given: list[str], rosrun_only: bool) -> list[tuple[Path | None, dict[str, str]]]:
    """The configurations to check in root: the launch files given (or found), then the rosrun one."""
    if rosrun_only:
        return [(None, {})]
    if not given:
        return [*((launch, {}) for launch in launch_files(root)), (None, {})]
    chosen: list[tuple[Path | None, dict[str, str]]] = []
    for spec in given:
        path, *pairs = spec.split()
        chosen.append((root / path, dict(pair.split(":=", 1) for pair in pairs)))
    return [*chosen, (None, {})]


def _child(root: Path, launch: Path | None, args: dict[str, str], conn: Connection) -> None:
    os.setpgrp()  # its own process group, so that a timeout also ends the C++ workers it starts
    conn.send(check(root, launch, args))
    conn.close()


def check_limited(root: Path, launch: Path | None, args: dict[str, str], limit: float) -> Run:
    """`check` in a child process, ended (with its process group) after `limit` seconds. The child
    is spawned, so that it imports archlog afresh: one consistent version of it per run."""
    receiver, sender = multiprocessing.Pipe(duplex=False)
    child = multiprocessing.get_context("spawn").Process(target=_child, args=(root, launch, args, sender))
    start = time.perf_counter()
    child.start()
    sender.close()
    run = None
    if receiver.poll(limit):
        try:
            run = receiver.recv()
        except EOFError:  # it died before answering
            child.join(10)
    if run is None:
        timed_out = child.is_alive()
        run = Run(str(root), label(root, launch, args), args, timeout=timed_out,
                  crash=None if timed_out else f"child process died (exit code {child.exitcode})")
        run.seconds = round(time.perf_counter() - start, 2)
    child.join(0 if run.timeout else 30)
    if child.is_alive() and child.pid is not None:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(child.pid, signal.SIGKILL)
        child.join()
    return run


def summary_row(root: Path, runs: list[Run]) -> dict:
    """One table row: totals over a repository's runs."""
    diags: collections.Counter[str] = collections.Counter()
    rules: collections.Counter[str] = collections.Counter()
    for run in runs:
        diags.update(run.diagnostics)
        rules.update(f["rule"] for f in run.findings)
    return {"repository": root.name, "launch files": sum(r.launch != ROSRUN for r in runs),
            "crashes": sum(r.crash is not None for r in runs), "timeouts": sum(r.timeout for r in runs),
            "nodes": sum(r.nodes for r in runs), "ports": sum(r.ports for r in runs),
            "QoS ports / pairs": f"{sum(r.qos_ports for r in runs)} / {sum(r.qos_pairs for r in runs)}",
            "diagnostics": ", ".join(f"{c} {n}" for c, n in diags.most_common()),
            "findings": ", ".join(f"{c} {n}" for c, n in sorted(rules.items())),
            "seconds": round(sum(r.seconds for r in runs), 1)}


def distinct_findings(runs: list[Run]) -> list[str]:
    """Each finding once (rule, file:line, message), with how often it was reported and where first."""
    seen: dict[tuple[str, str, int, str], list[str]] = {}
    for run in runs:
        for f in run.findings:
            seen.setdefault((f["rule"], f["file"], f["line"], f["message"]), []).append(run.launch)
    return [f"- {rule} {file}:{line} ({len(where)}x, first in {where[0]}): {message}"
            for (rule, file, line, message), where in sorted(seen.items())]


def markdown(rows: list[dict]) -> str:
    head = list(rows[0])
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(str(row[k]) for k in head) + " |" for row in rows]
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("roots", nargs="+", type=Path)
    parser.add_argument("--timeout", type=float, default=600, help="seconds per configuration")
    parser.add_argument("--json", type=Path, help="write every run (findings, crashes) here")
    parser.add_argument("--show", type=int, default=3, help="tracebacks to print per repository")
    parser.add_argument("--findings", action="store_true", help="also list every distinct finding")
    parser.add_argument("--config", action="append", default=[],
                        help="a launch file relative to each ROOT, with its name:=value arguments (repeatable)")
    parser.add_argument("--rosrun-only", action="store_true", help="check only the rosrun configuration")
    opts = parser.parse_args()
    rows, everything = [], []
    for root in (r.resolve() for r in opts.roots):
        runs = []
        for launch, args in configurations(root, opts.config, opts.rosrun_only):
            run = check_limited(root, launch, args, opts.timeout)
            status = "CRASH" if run.crash else "TIMEOUT" if run.timeout else "ok"
            print(f"{root.name}: {run.launch}: {status}, {run.nodes} nodes, {run.ports} ports, "
                  f"{len(run.findings)} findings, {run.seconds} s", file=sys.stderr, flush=True)
            runs.append(run)
        rows.append(summary_row(root, runs))
        everything += runs
        for run in [r for r in runs if r.crash][: opts.show]:
            print(f"CRASH {root.name}/{run.launch}\n{run.crash}", file=sys.stderr)
    print(markdown(rows))
    if opts.findings:
        print("\n".join(["", *distinct_findings(everything)]))
    if opts.json:
        opts.json.write_text(json.dumps([asdict(r) for r in everything], indent=1), encoding="utf-8")


if __name__ == "__main__":
    main()
