"""Benchmark: C++ extraction per translation unit, cold (empty result cache) and warm, and the
share of API calls fully resolved.

    python bench/cpp_bench.py [PATH...]

Uses a fresh cache folder; the one-time PCH build for ros/ros.h is timed separately.
"""

from __future__ import annotations

import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace import Workspace

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    roots = [Path(p) for p in sys.argv[1:]] or [ROOT / "corpus" / "ros1"]
    with tempfile.TemporaryDirectory() as cache:
        os.environ["ARCHLOG_CACHE_DIR"] = cache
        from archlog.extract.cpp import CppEnvironment, extract_cpp
        from archlog.extract.msg_headers import generated_headers

        sink = DiagnosticSink()
        jobs = []
        for root in roots:
            workspace = Workspace([root], sink)
            start = time.perf_counter()
            env = CppEnvironment([d for p in workspace.packages.values() for d in [p.path / "include", *p.include_dirs]],
                                 generated_headers(workspace, sink))
            setup = time.perf_counter() - start
            jobs += [(source, exe, env) for p in workspace.packages.values() for exe in p.executables.values()
                     if exe.lang == "cpp" for source in exe.sources if source.is_file()]
        print(f"environment (PCH build, message headers): {setup:.2f} s (once per machine / workspace content)")
        cold, warm, ports = [], [], []
        for source, exe, env in jobs:
            for times in (cold, warm):
                start = time.perf_counter()
                summary = extract_cpp([source], exe.package, exe.name, env, {}, sink)
                times.append(time.perf_counter() - start)
            ports += [p for p in summary.ports if p.kind != "timer"]
    from python_bench import known  # same definition of "resolved" as for Python

    resolved = [p for p in ports if known(p.name) and (known(p.handle_ns) or str(p.name).startswith(("/", "~")))
                and (p.kind.startswith("param") or known(p.type))]
    print(f"{len(jobs)} translation units: cold median {statistics.median(cold):.3f} s (max {max(cold):.3f}), "
          f"warm median {statistics.median(warm) * 1000:.1f} ms")
    print(f"{len(ports)} API calls, {len(resolved)} fully resolved ({100 * len(resolved) / max(len(ports), 1):.1f}%)")


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).parent))
    main()
