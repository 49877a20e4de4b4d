"""Survey: interpret every ROS 2 launch file (Python, XML, YAML) under the given folders.

    python bench/launch2_survey.py PATH... [--show N] [--verbose]

Each PATH is one repository (indexed as the workspace, so $(find-pkg-share) finds its packages).
Per repository: the ROS 2 launch files by dialect, archlog crashes (must be 0), and how many
were interpreted fully (no unknown value, no unresolved condition, no error), partially (some
unknown or conditional part, or an error in part of the file), or not at all (the file could not
be read: a parse error, no generate_launch_description). Partial files whose only gaps come from
packages outside the repository (not found by $(find-pkg-share)) are counted apart. Times are wall
clock per file, after the workspace is indexed.
"""

from __future__ import annotations

import argparse
import collections
import re
import sys
import time
import traceback
from pathlib import Path

import yaml
from lxml import etree

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from archlog.diagnostics import DiagnosticSink  # noqa: E402
from archlog.extract.launch.load import ros2_marker  # noqa: E402
from archlog.extract.launch.ros1 import LaunchInterpreter  # noqa: E402
from archlog.extract.workspace.index import Workspace  # noqa: E402
from archlog.extract.workspace.packages import SKIP_DIRS  # noqa: E402

PARTIAL = {"launch-unknown", "launch-condition"}  # notes that still mean "not all of it is known"
UNREAD = {"launch-python", "launch-xml", "launch-yaml", "not-a-file", "outside-workspace", "too-large"}  # not read
MISSING_PACKAGE = re.compile(r"package '[^']+' not found")
IGNORED = {"launch-arg-unknown", "launch-process", "no-model", "package-xml", "duplicate-package"}


def dialect(path: Path) -> str | None:
    """'python', 'xml' or 'yaml' for a ROS 2 launch file, else None."""
    try:
        content = path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return None
    if path.suffix == ".py":
        return "python" if re.search(r"^def generate_launch_description", content, re.M) else None
    if path.suffix in (".yaml", ".yml"):
        try:
            data = yaml.safe_load(content)
        except yaml.YAMLError:
            return "yaml" if content.lstrip().startswith("launch:") else None
        return "yaml" if isinstance(data, dict) and list(data) == ["launch"] else None
    if path.suffix in (".xml", ".launch"):
        try:
            root = etree.fromstring(content.encode())
        except etree.XMLSyntaxError:
            return None
        return "xml" if root.tag == "launch" and ros2_marker(root) is not None else None
    return None


def launch_files(folder: Path) -> list[tuple[Path, str]]:
    found = []
    for path in sorted(folder.rglob("*")):
        if not path.is_file() or any(part in SKIP_DIRS for part in path.relative_to(folder).parts):
            continue
        kind = dialect(path)
        if kind is not None:
            found.append((path, kind))
    return found


def classify(loaded: bool, sink: DiagnosticSink) -> tuple[str, list[str]]:
    """'full', 'partial' or 'none', with the diagnostics that decided it."""
    reasons = [str(d) for d in sink.items if d.code not in IGNORED and (d.severity != "note" or d.code in PARTIAL)]
    if not loaded:
        return "none", reasons
    return ("partial" if reasons else "full"), reasons


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("paths", nargs="+", type=Path)
    parser.add_argument("--show", type=int, default=5, help="how many partial/none files to explain")
    parser.add_argument("--verbose", action="store_true", help="print every file's verdict")
    opts = parser.parse_args()
    total: collections.Counter[str] = collections.Counter()
    for folder in opts.paths:
        files = launch_files(folder)
        index_sink = DiagnosticSink()
        start = time.perf_counter()
        workspace = Workspace([folder], index_sink)
        index_time = time.perf_counter() - start
        counts: collections.Counter[str] = collections.Counter()
        crashes, explained, times, nodes = [], [], [], 0
        for path, kind in files:
            counts[kind] += 1
            sink = DiagnosticSink()
            workspace.diagnostics = sink
            start = time.perf_counter()
            try:
                interpreter = LaunchInterpreter(workspace, sink)
                config = interpreter.load([path], {})
            except Exception:  # the point of the survey: any exception is a crash to report
                crashes.append((path, traceback.format_exc(limit=4)))
                continue
            times.append(time.perf_counter() - start)
            nodes += len(config.nodes)
            unread = any(d.code in UNREAD and d.file == workspace.display(path) for d in sink.items)
            verdict, reasons = classify(not unread, sink)
            counts[verdict] += 1
            if verdict == "partial" and all(MISSING_PACKAGE.search(r) for r in reasons):
                counts["missing"] += 1
            if opts.verbose:
                print(f"  {verdict:7} {len(config.nodes):3} nodes  {path.relative_to(folder)}")
            if verdict != "full":
                explained.append((path, verdict, reasons))
        total.update(counts)
        total["crashes"] += len(crashes)
        mean = sum(times) / len(times) * 1000 if times else 0.0
        print(f"{folder.name}: {len(files)} ROS 2 launch files (python {counts['python']}, xml {counts['xml']}, "
              f"yaml {counts['yaml']}); {len(crashes)} crashes; fully {counts['full']}, partially "
              f"{counts['partial']} ({counts['missing']} only for want of a package outside the repository), "
              f"not at all {counts['none']}; {nodes} nodes; "
              f"{mean:.1f} ms/file mean, {max(times, default=0) * 1000:.0f} ms max (+{index_time:.2f} s indexing)")
        for path, trace in crashes[: opts.show]:
            print(f"  CRASH {path}\n{trace}")
        for path, verdict, reasons in explained[: opts.show]:
            print(f"  {verdict.upper()} {path.relative_to(folder)}")
            for reason in reasons[:4]:
                print(f"    {reason}")
    if len(opts.paths) > 1:
        print(f"total: {total['full'] + total['partial'] + total['none']} files, {total['crashes']} crashes, "
              f"fully {total['full']}, partially {total['partial']} ({total['missing']} only for want of a package), "
              f"not at all {total['none']}")


if __name__ == "__main__":
    main()
