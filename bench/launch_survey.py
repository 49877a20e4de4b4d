"""Survey: interpret every ROS 1 launch file under the given folders with archlog and with
roslaunch (Debian's, run without executing anything), and count agreement.

    python bench/launch_survey.py PATH... [--show N]

Counts: files found, archlog crashes (must be 0), files roslaunch loads, and of those the ones
where nodes, remaps and parameters agree. Disagreements are listed (up to --show).
"""

from __future__ import annotations

import argparse
import sys
import time
import traceback
from pathlib import Path

from lxml import etree

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))

from support.launch_oracle import archlog_view, roslaunch_view  # noqa: E402


def launch_files(folder: Path) -> list[Path]:
    found = []
    for path in sorted(folder.rglob("*")):
        if path.suffix not in (".launch", ".xml") or not path.is_file():
            continue
        try:
            root = etree.parse(str(path)).getroot()
        except (etree.XMLSyntaxError, OSError):
            root = None
        if path.suffix == ".launch" or (root is not None and root.tag == "launch"):
            found.append(path)
    return found


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("paths", nargs="+", type=Path)
    parser.add_argument("--show", type=int, default=10)
    opts = parser.parse_args()
    for folder in opts.paths:
        files = launch_files(folder)
        crashes, loaded, agree, differ = [], 0, 0, []
        start = time.perf_counter()
        for path in files:
            try:
                ours = archlog_view([path], {}, [folder])
            except Exception:  # the point of the survey: any exception is a crash to report
                crashes.append((path, traceback.format_exc(limit=3)))
                continue
            theirs = roslaunch_view([path], {}, [folder])
            if theirs.error:
                continue
            loaded += 1
            if ours.error is None and (ours.nodes, ours.params) == (theirs.nodes, theirs.params):
                agree += 1
            else:
                differ.append((path, ours, theirs))
        print(f"{folder.name}: {len(files)} launch files, {len(crashes)} archlog crashes, "
              f"{loaded} loaded by roslaunch, {agree} agree, {len(differ)} differ "
              f"({time.perf_counter() - start:.1f} s)")
        for path, trace in crashes[: opts.show]:
            print(f"  CRASH {path}\n{trace}")
        for path, ours, theirs in differ[: opts.show]:
            print(f"  DIFFER {path.relative_to(folder)}")
            for name in sorted(set(ours.nodes) ^ set(theirs.nodes)):
                print(f"    node only in {'archlog' if name in ours.nodes else 'roslaunch'}: {name}")
            for name in sorted(set(ours.nodes) & set(theirs.nodes)):
                if ours.nodes[name] != theirs.nodes[name]:
                    print(f"    node {name}: archlog {ours.nodes[name]} roslaunch {theirs.nodes[name]}")
            keys = set(ours.params) | set(theirs.params)
            for key in sorted(k for k in keys if ours.params.get(k, "<none>") != theirs.params.get(k, "<none>"))[:5]:
                print(f"    param {key}: archlog {ours.params.get(key, '<none>')!r} "
                      f"roslaunch {theirs.params.get(key, '<none>')!r}")
            if ours.error:
                print(f"    archlog error: {ours.error}")


if __name__ == "__main__":
    main()
