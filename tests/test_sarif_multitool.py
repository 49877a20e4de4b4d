"""SARIF that GitHub code scanning accepts: Microsoft's SARIF Multitool (`validate --rule-kind Gh`)
reports zero errors and zero warnings on archlog's output."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import CORPUS, ROOT, load_case
from support.multitool import MULTITOOL, multitool_problems

pytestmark = pytest.mark.skipif(not MULTITOOL.is_file() and not os.environ.get("CI"),
                                reason="run `npm ci` in tests/sarif-multitool (bash .ci/run does)")
VARIANTS = [CORPUS / "topic_typo" / "buggy", CORPUS / "misplaced_remap" / "buggy", CORPUS / "wrong_remap" / "clean",
            CORPUS / "unused_remap_duplicate" / "buggy"]


def sarif_for(variant: Path, out: Path) -> Path:
    launches = [w for spec in load_case(variant)["launch"] for w in ("--launch", spec)]
    subprocess.run([sys.executable, "-m", "archlog", "check", str(variant), *launches, "--format", "sarif",
                    "--output", str(out), "--fail-on", "never"], cwd=ROOT, check=True, timeout=300)
    return out


@pytest.mark.parametrize("variant", VARIANTS, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_multitool_accepts_archlog_sarif(variant: Path, tmp_path: Path) -> None:
    sarif = sarif_for(variant, tmp_path / "report.sarif")
    assert json.loads(sarif.read_text())["runs"][0]["tool"]["driver"]["rules"]
    assert multitool_problems(sarif, tmp_path) == []


def test_multitool_catches_a_broken_report(tmp_path: Path) -> None:
    """The validator itself works: a result without a location is an error for GitHub."""
    document = json.loads(sarif_for(VARIANTS[0], tmp_path / "report.sarif").read_text())
    document["runs"][0]["results"][0].pop("locations")
    broken = tmp_path / "broken.sarif"
    broken.write_text(json.dumps(document))
    assert any(level == "error" for level, _rule, _msg in multitool_problems(broken, tmp_path))
