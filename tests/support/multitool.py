"""Microsoft's SARIF Multitool (tests/sarif-multitool, `npm ci`), run as GitHub code scanning's rules
(`validate --rule-kind Gh`)."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

MULTITOOL = Path(__file__).resolve().parent.parent / "sarif-multitool" / "node_modules" / "@microsoft" / \
    "sarif-multitool-linux" / "Sarif.Multitool"


def multitool_problems(sarif: Path, tmp_path: Path) -> list[tuple[str, str, str]]:
    """(level, rule, message) of every problem the Multitool finds in a SARIF file."""
    result = tmp_path / f"{sarif.stem}.validation.sarif"
    env = dict(os.environ, DOTNET_SYSTEM_GLOBALIZATION_INVARIANT="1")
    subprocess.run([str(MULTITOOL), "validate", "--rule-kind", "Gh", "--log", "ForceOverwrite", "-o", str(result),
                    str(sarif)], env=env, capture_output=True, text=True, timeout=300, check=True)
    runs = json.loads(result.read_text())["runs"]
    return [(r.get("level", "warning"), r["ruleId"], json.dumps(r["message"])[:200])
            for run in runs for r in run.get("results", [])]
