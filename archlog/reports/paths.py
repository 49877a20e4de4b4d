"""Where report paths are relative to: one source root for every format (docs/code-review.md).

Facts name files relative to the analysed PATH that holds them. Code review needs them relative to
the repository (GitHub puts an alert on `src/pkg/x.py`, not on `pkg/x.py`), so reports rebase
every file onto a source root: `--source-root DIR`, else the git work tree holding the first PATH,
else the current folder when it holds the first PATH, else the first PATH itself.
"""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

from archlog.diagnostics import Diagnostic
from archlog.reports.report import NodeCoverage, Report
from archlog.rules.engine import Finding, Location


def git_work_tree(path: Path) -> Path | None:
    """The work tree holding `path`: the nearest folder with a `.git` folder or file (a worktree or
    submodule has a file); nothing is run."""
    start = path.resolve()
    for folder in [start, *start.parents] if start.is_dir() else start.parents:
        if (folder / ".git").exists():
            return folder
    return None


def source_root(first: Path, given: Path | None = None) -> Path:
    """The folder report paths are relative to (see the module docstring)."""
    if given is not None:
        return given.resolve()
    tree = git_work_tree(first)
    if tree is not None:
        return tree
    here, path = Path.cwd().resolve(), first.resolve()
    if path == here or path.is_relative_to(here):
        return here
    return path if path.is_dir() else path.parent


class Rebase:
    """Turns a file as the facts name it (relative to one of the analysed roots, or absolute) into
    one relative to the source root; a file outside the source root stays absolute."""

    def __init__(self, roots: list[Path], root: Path) -> None:
        self.bases = [r if r.is_dir() else r.parent for r in roots]
        self.root = root
        self.rebased: dict[str, str] = {}  # a report names few files, many times

    def absolute(self, file: str) -> Path:
        if not file or os.path.isabs(file):
            return Path(file)
        # the facts name a file relative to the first root holding it, or as given on the command line
        for base in [*self.bases, Path.cwd()]:
            if os.path.lexists(base / file):
                return base / file
        return self.bases[0] / file if self.bases else Path(file)

    def __call__(self, file: str) -> str:
        if not file:
            return file
        if file not in self.rebased:
            path = self.absolute(file)
            self.rebased[file] = path.relative_to(self.root).as_posix() if path.is_relative_to(self.root) \
                else path.as_posix()
        return self.rebased[file]

    def location(self, loc: Location) -> Location:
        return replace(loc, file=self(loc.file))

    def finding(self, finding: Finding) -> Finding:
        return replace(finding, location=self.location(finding.location),
                       related=[self.location(r) for r in finding.related])

    def diagnostic(self, diag: Diagnostic) -> Diagnostic:
        return replace(diag, file=self(diag.file))

    def coverage(self, node: NodeCoverage) -> NodeCoverage:
        return replace(node, reasons=[(why, self(file), line) for why, file, line in node.reasons])

    def report(self, report: Report) -> Report:
        """The report with every file relative to the source root, which becomes its root."""
        return replace(report, root=self.root, findings=[self.finding(f) for f in report.findings],
                       diagnostics=[self.diagnostic(d) for d in report.diagnostics],
                       origins={node: [(self.location(loc), text) for loc, text in chain]
                                for node, chain in report.origins.items()},
                       coverage=[self.coverage(c) for c in report.coverage],
                       labels={(self(file), line, column): text
                               for (file, line, column), text in report.labels.items()},
                       holes=[(why, self(file), line) for why, file, line in report.holes])
