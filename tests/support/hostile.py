"""Run archlog on a hostile workspace the way CI on a pull request would, and judge the run.

Each case runs `python -m archlog check` in a subprocess with resource limits (time and address
space), a canary environment variable and a canary file outside the workspace. A run is judged on
four counts: no execution (no marker file appears), no leak (no canary in any output), no
traceback, within budget (finished in time, exit status 0, 1 or 2).
"""

from __future__ import annotations

import os
import resource
import secrets
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

TIME_LIMIT = 20.0
MEMORY_LIMIT = 1 << 30
CANARY_ENV = "ARCHLOG_CANARY_SECRET"


@dataclass
class Outside:
    """Things outside the workspace a hostile case may try to reach: a secret file, a secret
    environment variable and a folder where an executed payload would leave a marker."""

    root: Path
    secret: str = field(default_factory=lambda: "canary-" + secrets.token_hex(8))

    def __post_init__(self) -> None:
        self.root.mkdir(parents=True, exist_ok=True)
        self.secret_file.write_text(f"password: {self.secret}\n{self.secret}\n")
        self.markers.mkdir(exist_ok=True)

    @property
    def secret_file(self) -> Path:
        return self.root / "secret.yaml"

    @property
    def markers(self) -> Path:
        return self.root / "markers"

    def marker(self, name: str = "pwned") -> Path:
        return self.markers / name


@dataclass
class Run:
    returncode: int | None
    output: str
    seconds: float

    @property
    def timed_out(self) -> bool:
        return self.returncode is None


def _limits() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    os.setsid()


def run_check(workspace: Path, outside: Outside, *options: str, fmt: str = "text",
              time_limit: float = TIME_LIMIT) -> Run:
    """`archlog check WORKSPACE OPTIONS --format FMT`, its report written to a file and read back
    together with stdout and stderr."""
    report = outside.root / f"report.{fmt}"
    report.unlink(missing_ok=True)
    env = {k: v for k, v in os.environ.items() if not k.startswith("ARCHLOG_CANARY")}
    env[CANARY_ENV] = outside.secret
    cmd = [sys.executable, "-m", "archlog", "check", str(workspace), *options, "--format", fmt,
           "--output", str(report), "--fail-on", "never"]
    begin = time.monotonic()
    process = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                               cwd=workspace, preexec_fn=_limits, text=True, errors="replace")
    try:
        out, _ = process.communicate(timeout=time_limit)
        code: int | None = process.returncode
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, 9)
        out, _ = process.communicate()
        code = None
    written = report.read_text(errors="replace") if report.is_file() else ""
    return Run(code, out + written, time.monotonic() - begin)


def problems(run: Run, outside: Outside) -> list[str]:
    """What is wrong with a run: execution, leak, traceback, over budget; empty when nothing."""
    found = []
    if any(outside.markers.iterdir()):
        found.append(f"executed: {sorted(p.name for p in outside.markers.iterdir())}")
    if outside.secret in run.output:
        found.append("leaked the canary")
    if "Traceback" in run.output or "internal error" in run.output:
        found.append("traceback: " + run.output[-1500:])
    if run.timed_out:
        found.append(f"over budget: still running after {run.seconds:.0f} s")
    elif run.returncode not in (0, 1, 2):
        found.append(f"exit status {run.returncode} (killed? memory?): {run.output[-800:]}")
    return found
