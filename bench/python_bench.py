"""Benchmark: rospy/rclpy extraction throughput in files per second.

    python bench/python_bench.py [PATH...]

Without paths it measures corpus/ (small); give large trees (e.g. fetched ROS repositories) for
a real figure. Every .py file is extracted, whether or not it is a node.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.python import extract_python
from archlog.values import Concat, ParamRef, Unknown

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    roots = [Path(p) for p in sys.argv[1:]] or [ROOT / "corpus"]
    files = [p for root in roots for p in sorted(root.rglob("*.py")) if p.is_file()]
    sink = DiagnosticSink()
    start = time.perf_counter()
    summaries = [extract_python(p, "bench", p.name, str(p), sink) for p in files]
    seconds = time.perf_counter() - start
    lines = sum(len(p.read_bytes().splitlines()) for p in files)
    ports = [port for s in summaries for port in s.ports if port.kind != "timer"]
    resolved = [p for p in ports if known(p.name) and (p.kind.startswith("param") or known(p.type))]
    print(f"{len(files)} files ({lines} lines): {seconds:.2f} s, {len(files) / seconds:.0f} files/s, "
          f"{lines / seconds:.0f} lines/s")
    print(f"{len(ports)} API calls found, {len(resolved)} fully resolved "
          f"({100 * len(resolved) / max(len(ports), 1):.1f}%); {len(sink.items)} diagnostics")


def known(value: object) -> bool:
    """Resolved statically: a literal, or a parameter read whose default is known."""
    if isinstance(value, ParamRef):
        return known(value.default)
    if isinstance(value, Concat):
        return all(known(p) for p in value.parts)
    return not isinstance(value, Unknown)


if __name__ == "__main__":
    main()
