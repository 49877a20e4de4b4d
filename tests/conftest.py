"""Shared helpers for the test suite."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from archlog.analysis import analyse
from archlog.config import load_config
from archlog.rules.engine import Engine, Finding, render
from archlog.rules.ruleset import load_rules

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "corpus" / "ros1"
CORPUS_ROS2 = ROOT / "corpus" / "ros2"
CORPUS_BEHAVIOR = ROOT / "corpus" / "behavior"  # ROS 1 systems with expected behavior models (issue 9)
# The SARIF 2.1.0 schema as Microsoft's SARIF Multitool package ships it (MIT licence; `npm ci` in
# tests/sarif-multitool, which .ci/run does): the tests need nothing outside the repository.
SARIF_SCHEMA = ROOT / "tests" / "sarif-multitool" / "node_modules" / "@microsoft" / "sarif-multitool-linux" / "sarif-2.1.0.json"


def corpus_cases(corpus: Path = CORPUS) -> list[Path]:
    return sorted(p.parent for p in corpus.glob("*/*/case.json"))


def load_case(variant: Path) -> dict:
    return json.loads((variant / "case.json").read_text())


def run_case(variant: Path) -> tuple[object, list[Finding]]:
    """The case's findings; the operator tools of its archlog.toml, if any, are part of the system."""
    case = load_case(variant)
    config = variant / "archlog.toml"
    operators = load_config(config, None).operators if config.is_file() else []
    analysis = analyse([variant], case["launch"], case.get("args", {}),
                       [variant / m for m in case.get("models", [])] + operators)
    _ctl, findings = Engine(load_rules([])).run(analysis.store)
    return analysis, findings


def finding_keys(findings: list[Finding]) -> list[tuple[str, str, int, str]]:
    """(rule, file, line, subject): the subject is a finding's first column by convention."""
    return sorted((f.rule.id, f.location.file, f.location.line, render(next(iter(f.values.values()))))
                  for f in findings)


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-goldens", action="store_true", default=False,
                     help="rewrite every golden file the tests compare with (corpus case.json findings, *.expected "
                          "files, rule fixtures, generated docs) from the current results; review the diff")


@pytest.fixture(scope="session")
def update_goldens(request: pytest.FixtureRequest) -> bool:
    """True under `pytest --update-goldens` (tests/support/goldens.py lists the golden files)."""
    return bool(request.config.getoption("--update-goldens"))


@pytest.fixture(scope="session", autouse=True)
def private_cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Every run (and the CLI subprocesses it starts) uses a fresh archlog cache folder."""
    import os

    folder = tmp_path_factory.mktemp("archlog-cache")
    os.environ["ARCHLOG_CACHE_DIR"] = str(folder)
    return folder


@pytest.fixture(scope="session")
def sarif_schema() -> dict:
    """The SARIF 2.1.0 JSON schema; in CI a missing schema is a failure, elsewhere a skip."""
    import os

    if not SARIF_SCHEMA.is_file():
        message = f"the SARIF schema comes with `npm ci` in tests/sarif-multitool: {SARIF_SCHEMA} is missing"
        if os.environ.get("CI"):
            pytest.fail(message)
        pytest.skip(message)
    return json.loads(SARIF_SCHEMA.read_text())


def requires_ros() -> list:
    """Marks for tests that run Debian's ROS 1; in CI (CI set) a missing ROS is a failure, not a skip."""
    import os

    from support.live_graph import ros_available

    return [pytest.mark.ros,
            pytest.mark.skipif(not ros_available() and not os.environ.get("CI"), reason="Debian ROS 1 not installed")]


def requires_rclpy() -> list:
    """Marks for tests that start rclpy nodes (archlog's ros2 extra); in CI a missing rclpy is a
    failure, not a skip."""
    import os

    from support.ros2_nodes import rclpy_available

    return [pytest.mark.ros2,
            pytest.mark.skipif(not rclpy_available() and not os.environ.get("CI"),
                               reason="rclpy is not importable (pip install 'archlog[ros2]')")]
