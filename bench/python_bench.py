"""Benchmark: rospy/rclpy extraction throughput, the share of API calls fully resolved, and the
share of publish calls whose trigger is recovered (timer, loop, callback or start-up rather than
unknown; ROSInfer reports 87%), per system (each PATH is one), for rospy and rclpy apart.

    python bench/python_bench.py [PATH...]

Without paths it measures corpus/ (small); give large trees (e.g. fetched ROS repositories) for
a real figure. Every .py file is extracted, whether or not it is a node; launch files and tests
count as files but rarely have API calls.
"""

from __future__ import annotations

import sys
import time
from collections import Counter, defaultdict
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.python.node import extract_python
from archlog.extract.summary import TRIGGERS, Port, Publish
from archlog.values import Concat, ParamRef, Unknown

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    roots = [Path(p) for p in sys.argv[1:]] or [ROOT / "corpus"]
    for root in roots:
        files = [p for p in sorted(root.rglob("*.py")) if p.is_file()]
        sink = DiagnosticSink()
        start = time.perf_counter()
        summaries = [(p, extract_python(p, "bench", p.name, str(p), sink)) for p in files]
        seconds = time.perf_counter() - start
        lines = sum(len(p.read_bytes().splitlines()) for p in files)
        print(f"{root.name}: {len(files)} files ({lines} lines): {seconds:.2f} s, "
              f"{len(files) / max(seconds, 1e-9):.0f} files/s, {lines / max(seconds, 1e-9):.0f} lines/s; "
              f"{len(sink.items)} diagnostics")
        for family in ("rospy", "rclpy"):
            ports = [port for path, s in summaries if _family(path) == family for port in s.ports
                     if port.kind != "timer"]
            if ports:
                print(f"  {family}: {resolution(ports)}")
            publishes = [p for path, s in summaries if _family(path) == family for p in s.publishes]
            if publishes:
                print(f"  {family}: {triggers(publishes)}")
            in_nodes = [p for path, s in summaries if _family(path) == family and s.default_name is not None
                        for p in s.publishes]
            if in_nodes and len(in_nodes) < len(publishes):
                print(f"  {family}, files that make a node (not libraries): {triggers(in_nodes)}")


def _family(path: Path) -> str:
    text = path.read_text(errors="replace")
    return "rclpy" if "rclpy" in text else "rospy"


def known(value: object) -> bool:
    """Resolved statically: a literal, or a parameter read whose default is known."""
    if isinstance(value, ParamRef):
        return known(value.default)
    if isinstance(value, Concat):
        return all(known(p) for p in value.parts)
    return not isinstance(value, Unknown)


def resolution(ports: list[Port]) -> str:
    """API calls found, fully resolved (name and type known), and for ROS 2 the QoS known."""
    resolved = [p for p in ports if known(p.name) and (known(p.handle_ns) or str(p.name).startswith(("/", "~")))
                and (p.kind.startswith("param") or known(p.type))]
    text = f"{len(ports)} API calls, {len(resolved)} fully resolved ({100 * len(resolved) / len(ports):.1f}%)"
    topics = [p for p in ports if p.kind in ("publisher", "subscriber") and p.qos]
    if topics:
        qos = [p for p in topics if {"reliability", "durability"} <= dict(p.qos).keys()]
        text += f"; QoS reliability and durability known on {len(qos)} of {len(topics)} publishers and subscribers"
    return text


def triggers(publishes: list[Publish]) -> str:
    """Publish calls (one per file and line, however many ways each is reached), those with a
    recovered trigger on some path, per trigger, and those reached on no unknown path."""
    calls: dict[tuple[str, int], set[str]] = defaultdict(set)
    for publish in publishes:
        calls[(publish.file, publish.line)].add(publish.trigger)
    known = [kinds for kinds in calls.values() if kinds - {"unknown"}]
    counts = Counter(kind for kinds in calls.values() for kind in kinds)
    guarded = len({(p.file, p.line) for p in publishes if p.guards})
    return (f"{len(calls)} publish calls, trigger recovered for {len(known)} ({100 * len(known) / len(calls):.1f}%; "
            + ", ".join(f"{kind} {counts[kind]}" for kind in TRIGGERS if counts[kind])
            + f"), no unknown path for {sum('unknown' not in kinds for kinds in calls.values())}, guarded {guarded}")


if __name__ == "__main__":
    main()
