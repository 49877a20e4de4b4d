"""Benchmark: rospy/rclpy extraction throughput, and the share of API calls fully resolved, per
system (each PATH is one), for rospy and rclpy apart.

    python bench/python_bench.py [PATH...]

Without paths it measures corpus/ (small); give large trees (e.g. fetched ROS repositories) for
a real figure. Every .py file is extracted, whether or not it is a node; launch files and tests
count as files but rarely have API calls.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.python import extract_python
from archlog.extract.summary import Port
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


if __name__ == "__main__":
    main()
