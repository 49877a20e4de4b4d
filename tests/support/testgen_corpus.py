"""Run `archlog testgen` on a corpus/testgen system and the generated test against it (used by
tests/test_testgen.py and bench/testgen_bench.py).

A case (case.json) names its launch file(s) and arguments, and optionally a settings file
("settings") and a hand-written properties file ("properties", copied in as the user's file before
generating, which must not overwrite it). C++ nodes are built with g++ first (support.build_cpp).
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from support.build_cpp import build_workspace

ROOT = Path(__file__).resolve().parents[2]
CORPUS = ROOT / "corpus" / "testgen"


@dataclass
class Outcome:
    passed: bool
    seconds: float
    examples: int  # launches of the nodes under test (examples run, shrinking included)
    replay: dict | None  # the replay file of the failure, if one was written
    output: str
    coverage: dict[str, list[int]] = field(default_factory=dict)  # Python node -> [lines run, statements]

    def lines(self) -> str:
        """The line coverage of the Python nodes under test, as the bench tables show it."""
        return ", ".join(f"{node} {run}/{total}" for node, (run, total) in sorted(self.coverage.items())) or "-"

    def messages(self) -> int:
        """Input messages, service calls and goals in the replay (what the shrunk failure sends)."""
        return sum(a["op"] in ("publish", "call", "goal") for a in (self.replay or {}).get("actions", []))


def systems() -> list[Path]:
    return sorted(p.parent.parent for p in CORPUS.glob("*/buggy/case.json"))


def prepare(variant: Path, work: Path) -> tuple[Path, dict]:
    """Copy the variant to `work` (building its C++ nodes) and generate its test; returns the folder
    of the generated test and the case."""
    case = json.loads((variant / "case.json").read_text())
    workspace = build_workspace(variant, work / "ws").parent
    out = work / "generated"
    out.mkdir()
    stem = Path(case["launch"][0]).name.split(".")[0]
    if "properties" in case:
        shutil.copy(variant / case["properties"], out / f"{stem}_properties.py")
    command = [sys.executable, "-m", "archlog", "testgen", str(workspace), "--output", str(out)]
    command += [x for spec in case["launch"] for x in ("--launch", spec)]
    command += [x for k, v in case["args"].items() for x in ("--arg", f"{k}:={v}")]
    if "settings" in case:
        command += ["--settings", str(variant / case["settings"])]
    ros2 = any("ament_" in manifest.read_text() for manifest in workspace.rglob("package.xml"))
    subprocess.run(command, check=True, capture_output=True, text=True, timeout=120, env=ros2_prefix() if ros2 else None)
    return out, case


def ros2_prefix() -> dict[str, str]:
    """This environment, with ROS 2 installed from PyPI in this Python (if it is) on AMENT_PREFIX_PATH, as a
    ROS 2 setup file sets it: archlog then finds its interface definitions (an action's goal)."""
    env = dict(os.environ)
    if (Path(sys.prefix) / "share" / "ament_index").is_dir() and not env.get("AMENT_PREFIX_PATH"):
        env["AMENT_PREFIX_PATH"] = sys.prefix
    return env


def run_generated(out: Path, examples: int, seed: int, shrink_seconds: int = 60, steps: int | None = None,
                  timeout: float = 600) -> Outcome:
    """Run the generated test module in `out` with pytest (steps per example: the settings' max_messages
    unless given); the outcome and how long it took."""
    (out / "replay").exists() and shutil.rmtree(out / "replay")
    stats = out / "stats.json"
    stats.unlink(missing_ok=True)
    env = dict(os.environ, ARCHLOG_TESTGEN_EXAMPLES=str(examples), ARCHLOG_TESTGEN_SHRINK_SECONDS=str(shrink_seconds),
               ARCHLOG_TESTGEN_STATS=str(stats), **({"ARCHLOG_TESTGEN_STEPS": str(steps)} if steps else {}))
    start = time.monotonic()
    result = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-x",
                             f"--hypothesis-seed={seed}", str(out)], env=env, capture_output=True, text=True,
                            timeout=timeout, cwd=out)
    seconds = time.monotonic() - start
    replays = list((out / "replay").glob("*.json")) if (out / "replay").is_dir() else []
    replay = json.loads(replays[0].read_text()) if replays else None
    counts = json.loads(stats.read_text()) if stats.is_file() else {}
    return Outcome(result.returncode == 0, seconds, counts.get("launches", 0), replay, result.stdout[-20000:],
                   counts.get("coverage", {}))
