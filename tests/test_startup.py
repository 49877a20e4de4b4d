"""Start-up stays light: `archlog --version` and `--help` load none of the heavy libraries (they are
imported by the commands that use them)."""

from __future__ import annotations

import subprocess
import sys

import pytest

HEAVY = ("clang", "clingo", "lxml", "numpy", "rich", "rapidfuzz")
PROBE = """
import contextlib
import sys
from archlog.cli import main
with contextlib.suppress(SystemExit):
    main([{flag!r}], prog_name="archlog")
print("loaded:", ",".join(m for m in {heavy!r} if m in sys.modules))
"""


@pytest.mark.parametrize("flag", ["--version", "--help"])
def test_version_and_help_import_no_heavy_module(flag: str) -> None:
    done = subprocess.run([sys.executable, "-c", PROBE.format(flag=flag, heavy=HEAVY)], capture_output=True,
                          text=True, check=True)
    assert "archlog" in done.stdout.lower()
    assert done.stdout.strip().endswith("loaded:"), done.stdout


def test_a_commands_help_imports_no_heavy_module() -> None:
    probe = PROBE.replace("[{flag!r}]", "['check', '--help']").format(heavy=HEAVY)
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert "Usage: archlog check" in done.stdout
    assert done.stdout.strip().endswith("loaded:"), done.stdout
