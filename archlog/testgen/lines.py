"""Line coverage of the Python nodes under test: each node process runs under coverage.py and writes
its data file into one folder when it ends (ROS 2: coverage.py in this Python; ROS 1: Debian's
python3-coverage under /usr/bin/python3, the same data format). Read after every example, the lines
run for the first time steer generation (runtime: a Hypothesis target); at the end, per node, the
lines of its file run and its statements are in the report."""

from __future__ import annotations

import os
from pathlib import Path


class LineCoverage:
    """The coverage data of the nodes' processes in `folder`, for `files` (node -> its Python file)."""

    def __init__(self, folder: Path, files: dict[str, str]) -> None:
        self.folder = folder
        self.files = {node: os.path.realpath(file) for node, file in files.items()}
        self.seen: dict[str, set[int]] = {node: set() for node in files}
        self.read: set[Path] = set()  # data files already counted

    def new_lines(self) -> int:
        """How many lines of the nodes' files the processes that ended since the last call ran first."""
        from coverage import CoverageData

        new = 0
        for path in sorted(set(self.folder.glob("data.*")) - self.read):
            self.read.add(path)
            data = CoverageData(basename=str(path))
            data.read()
            measured = {os.path.realpath(f): f for f in data.measured_files()}
            for node, file in self.files.items():
                lines = set(data.lines(measured[file]) or ()) if file in measured else set()
                new += len(lines - self.seen[node])
                self.seen[node] |= lines
        return new

    def covered(self) -> dict[str, tuple[int, int]]:
        """Per node, the lines of its file run by any of its processes and the statements of the file
        (a file coverage.py cannot parse is left out)."""
        import coverage
        from coverage.exceptions import CoverageException

        self.new_lines()
        analyser = coverage.Coverage(data_file=None)
        found = {}
        for node, file in self.files.items():
            try:
                _file, statements, _excluded, _missing, _text = analyser.analysis2(file)
            except CoverageException:  # not Python 3 (a Python 2 script) or gone: no statements to count
                continue
            found[node] = (len(self.seen[node] & set(statements)), len(statements))
        return found
