"""Line coverage of the nodes under test (archlog/testgen/lines.py): the data files the nodes'
processes write under coverage.py are read after every example; only lines run for the first time
count as new (what a generated test gives Hypothesis as its target), and the report counts the lines
of each node's file run against its statements."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from archlog.testgen.lines import LineCoverage

pytest.importorskip("coverage", reason="coverage.py (the test extra) is not installed")

NODE = '''import sys

value = float(sys.argv[1])
if value > 0:
    print("positive")
elif value < 0:
    print("negative")
else:
    print("zero")
'''


def _run(script: Path, folder: Path, argument: str) -> None:
    """The script in a process of its own under coverage.py, its data file written into `folder` as a
    node's is (one file per process)."""
    subprocess.run([sys.executable, "-m", "coverage", "run", "--parallel-mode", f"--data-file={folder / 'data'}",
                    str(script), argument], check=True, capture_output=True, timeout=60)


def test_only_lines_run_for_the_first_time_are_new(tmp_path: Path) -> None:
    script = tmp_path / "node.py"
    script.write_text(NODE)
    folder = tmp_path / "coverage"
    lines = LineCoverage(folder, {"/node": str(script)})
    assert lines.new_lines() == 0  # no process ended yet
    _run(script, folder, "1")
    assert lines.new_lines() == 4  # the import, the assignment, the test and the positive branch
    assert lines.new_lines() == 0  # the same data file is not counted twice
    _run(script, folder, "2")
    assert lines.new_lines() == 0  # another process, the same lines
    _run(script, folder, "-1")
    assert lines.new_lines() == 2  # the second test and its branch
    assert lines.covered() == {"/node": (6, 7)}  # never zero


def test_a_file_coverage_cannot_parse_is_left_out_of_the_report(tmp_path: Path) -> None:
    script = tmp_path / "old.py"
    script.write_text('print "a Python 2 script"\n')
    assert LineCoverage(tmp_path / "coverage", {"/old": str(script)}).covered() == {}
