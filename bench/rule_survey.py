"""Findings per rule on real workspaces, to compare two versions of the rules (issue 21).

    python bench/rule_survey.py [--code DIR] [--evalsrc /work/evalsrc] [--system NAME=SRC:LAUNCH ...]

Runs `python -m archlog check --format json` from DIR (default: this checkout; give an exported
older tree to measure it) on the husky and turtlebot subjects of bench/eval_recovery.py (launch
files and environment from their experiment.yml) and on every --system given, and prints per system
the findings per rule, the opaque and partial node counts, and each finding's message.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from collections import Counter
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent


def subjects(evalsrc: Path) -> dict[str, list[str]]:
    """The check arguments of each eval_recovery subject found under EVALSRC."""
    found = {}
    for meta in sorted((evalsrc / "meta").glob("*/experiment.yml")):
        experiment, src = yaml.safe_load(meta.read_text()), evalsrc / meta.parent.name / "src"
        args = [str(src)]
        for launch in experiment["launches"]:
            args += ["--launch", launch.replace("/ros_ws/src", str(src))]
        for key, value in (experiment.get("environment") or {}).items():
            args += ["--env", f"{key}={str(value).replace('/ros_ws/src', str(src))}"]
        found[meta.parent.name] = args
    return found


def survey(code: Path, args: list[str]) -> dict:
    run = subprocess.run([sys.executable, "-m", "archlog", "check", *args, "--format", "json", "--fail-on", "never"],
                         cwd=code, capture_output=True, text=True, check=True)
    report = json.loads(run.stdout)
    return {"rules": dict(sorted(Counter(f["rule"] for f in report["findings"]).items())),
            "opaque": report["coverage"]["opaque"], "partial": report["coverage"]["partial"],
            "findings": sorted(f"{f['rule']} {f['message']}" for f in report["findings"])}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--code", type=Path, default=ROOT)
    parser.add_argument("--evalsrc", type=Path, default=Path("/work/evalsrc"))
    parser.add_argument("--system", action="append", default=[], help="NAME=SRC:LAUNCH")
    options = parser.parse_args()
    systems = subjects(options.evalsrc) if options.evalsrc.is_dir() else {}
    for spec in options.system:
        name, _, rest = spec.partition("=")
        src, _, launch = rest.partition(":")
        systems[name] = [src, "--launch", launch]
    print(json.dumps({name: survey(options.code, args) for name, args in systems.items()}, indent=1))


if __name__ == "__main__":
    main()
