"""`archlog check --new-only --base REF`: the findings a change introduces.

REF's tree of the git work tree holding the first PATH is written to a temporary folder
(`git archive`, extracted with tarfile's `data` filter: no links out, no devices); the same
system is analysed there, and a finding whose fingerprint (its rule and resolved names, not its
line) the base has too is pre-existing.
"""

from __future__ import annotations

import io
import os
import subprocess
import tarfile
from pathlib import Path

from archlog.errors import ConfigError
from archlog.reports.paths import git_work_tree


def work_tree(first: Path) -> Path:
    tree = git_work_tree(first)
    if tree is None:
        raise ConfigError(f"--new-only needs a git work tree; {first} is in none")
    return tree


def checkout(tree: Path, ref: str, dest: Path) -> None:
    """Write the files of `ref` in the repository at `tree` into `dest`."""
    try:
        archive = subprocess.run(["git", "-C", str(tree), "archive", "--format=tar", ref, "--"], capture_output=True,
                                 timeout=300, check=False)
    except (OSError, subprocess.TimeoutExpired) as exc:
        raise ConfigError(f"--base {ref}: cannot run git ({exc})") from None
    if archive.returncode != 0:
        why = archive.stderr.decode(errors="replace").strip().splitlines()
        raise ConfigError(f"--base {ref}: git archive failed: {why[-1] if why else archive.returncode}")
    with tarfile.open(fileobj=io.BytesIO(archive.stdout)) as tar:
        if hasattr(tarfile, "data_filter"):  # Python 3.11.4 and later: refuse links and paths out of `dest`
            tar.extractall(dest, filter="data")
        else:  # git archive of a commit writes only the repository's own paths
            tar.extractall(dest)


def moved(path: Path, tree: Path, dest: Path) -> Path:
    """A path inside the work tree as the same path inside `dest`; any other path as it is."""
    absolute = path.resolve()
    return dest / absolute.relative_to(tree) if absolute.is_relative_to(tree) else path


def moved_launch(launch: str, tree: Path, dest: Path) -> str:
    """A launch file given as a path inside the work tree, moved; `pkg/file` and others as they are."""
    return str(moved(Path(launch), tree, dest)) if os.path.exists(launch) else launch
