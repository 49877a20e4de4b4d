"""Benchmark: C++ extraction per translation unit, cold (empty result cache) and warm, the share
of API calls fully resolved, and the share of publish calls whose trigger is recovered (behavior:
timer, loop, callback or start-up on every way the call is reached, none unknown), per system
(each PATH is one), for roscpp and rclcpp apart; then the behavior totals over all systems.

    python bench/cpp_bench.py [PATH...]

Uses a fresh cache folder; the one-time PCH builds (ros/ros.h, the rclcpp stand-in) count in the
first system's setup and first translation unit. A translation unit is one source file read for
one executable class (a component library's file is read once per component it registers).
Behavior is measured per executable (its files together: a call in one file may be reached from
another), a publish call counted once however many executables read it.
"""

from __future__ import annotations

import os
import statistics
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

from archlog.diagnostics import DiagnosticSink
from archlog.extract.summary import Port, Publish
from archlog.extract.workspace.executables import registered_components
from archlog.extract.workspace.index import Workspace
from archlog.extract.workspace.packages import Executable

sys.path.insert(0, str(Path(__file__).parent))
from python_bench import resolution

ROOT = Path(__file__).resolve().parent.parent


def main() -> None:
    roots = [Path(p) for p in sys.argv[1:]] or [ROOT / "corpus" / d for d in ("ros1", "ros2", "cpp_ros2", "behavior")]
    calls: dict[tuple[str, int], list[Publish]] = {}
    with tempfile.TemporaryDirectory() as cache:
        os.environ["ARCHLOG_CACHE_DIR"] = cache
        for root in roots:
            calls.update({(f"{root}/{file}", line): ways for (file, line), ways in system(root).items()})
    if len(roots) > 1:
        print(f"all systems: {behavior(calls)}")


def behavior(calls: dict[tuple[str, int], list[Publish]]) -> str:
    """Publish calls, those whose trigger is recovered on every way, those whose publisher is
    known, those with a guard, and the ways by trigger."""
    if not calls:
        return "no publish calls"
    recovered = sum(all(w.trigger != "unknown" for w in ways) for ways in calls.values())
    publisher = sum(any(w.publisher is not None for w in ways) for ways in calls.values())
    guarded = sum(any(w.guards for w in ways) for ways in calls.values())
    triggers = Counter(t for ways in calls.values() for t, _source in {(w.trigger, w.source) for w in ways})
    return (f"{len(calls)} publish calls, trigger recovered on {recovered} ({100 * recovered / len(calls):.1f}%), "
            f"publisher known on {publisher} ({100 * publisher / len(calls):.1f}%), {guarded} guarded; ways: "
            + ", ".join(f"{t} {n}" for t, n in sorted(triggers.items())))


def system(root: Path) -> dict[tuple[str, int], list[Publish]]:
    from archlog.extract.cpp.extract import CppEnvironment, extract_cpp, is_ros2_source
    from archlog.extract.cpp.msg_headers import generated_headers

    sink = DiagnosticSink()
    start = time.perf_counter()
    workspace = Workspace([root], sink)
    env = CppEnvironment([d for p in workspace.packages.values() for d in [p.path / "include", *p.include_dirs]],
                         generated_headers(workspace, sink), workspace.roots)
    setup = time.perf_counter() - start
    units = sorted({(source, exe.cls): exe for p in workspace.packages.values() for exe in p.executables.values()
                    if exe.lang == "cpp" for source in exe.sources if source.is_file()}.items(), key=str)
    if not workspace.packages:  # loose files (corpus/cpp_ros2): each is a unit, a component as its class
        units = [((source, cls), Executable("bench", source.stem, "cpp", [source], 0, cls))
                 for source in sorted(root.rglob("*.cpp"))
                 for cls in [next(iter(registered_components(source.read_text())), (None,))[0]]]
    cold: list[float] = []
    warm: list[float] = []
    ports: dict[str, list[Port]] = {"roscpp": [], "rclcpp": []}
    calls: dict[str, dict[tuple[str, int], list[Publish]]] = {"roscpp": {}, "rclcpp": {}}
    incomplete = 0
    for (source, cls), exe in units:
        for times in (cold, warm):
            begin = time.perf_counter()
            summary = extract_cpp([source], exe.package, exe.name, env, {}, sink, cls)
            times.append(time.perf_counter() - begin)
        family = "rclcpp" if is_ros2_source(source, env) else "roscpp"
        ports[family] += [p for p in summary.ports if p.kind != "timer"]
        incomplete += summary.incomplete is not None
    executables = {(exe.package, exe.name, cls): exe for (_source, cls), exe in units}
    for (package, name, cls), exe in executables.items():  # every file read already: from the cache
        sources = [s for s in exe.sources if s.is_file()]
        family = "rclcpp" if is_ros2_source(sources[0], env) else "roscpp"
        for publish in extract_cpp(sources, package, name, env, {}, DiagnosticSink(), cls).publishes:
            ways = calls[family].setdefault((publish.file, publish.line), [])
            ways += [publish] if publish not in ways else []
    print(f"{root.name}: {len(units)} translation units, setup {setup:.2f} s (workspace, environment, PCH)")
    if units:
        print(f"  cold median {statistics.median(cold):.3f} s (max {max(cold):.3f}, total {sum(cold):.1f} s), "
              f"warm median {statistics.median(warm) * 1000:.1f} ms; {incomplete} incomplete; "
              f"{len(sink.items)} diagnostics")
    for family, found in ports.items():
        if found:
            print(f"  {family}: {resolution(found)}")
            print(f"  {family} behavior: {behavior(calls[family])}")
    return {**calls["roscpp"], **calls["rclcpp"]}


if __name__ == "__main__":
    main()
