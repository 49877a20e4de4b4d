"""Completeness is visible (issue 17): every `archlog check` says which nodes it recovered fully,
partly (why, and where) or not at all, in text, JSON and SARIF; --fail-on-incomplete; the
port-name-unknown note; `archlog diff` percentages over the observed count."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import jsonschema
import pytest
from conftest import ROOT

from archlog.observe import Architecture, compare

CASE = ROOT / "corpus" / "coverage" / "unrecovered_nodes"
JSON_SCHEMA = json.loads((ROOT / "archlog" / "reports" / "findings.schema.json").read_text())


def check(variant: Path, *args: str | Path) -> subprocess.CompletedProcess:
    """`archlog check` with paths relative to the variant, as case.json gives them."""
    case = json.loads((variant / "case.json").read_text())
    launches = [w for spec in case["launch"] for w in ("--launch", spec)]
    return subprocess.run([sys.executable, "-m", "archlog", "check", str(variant), *launches, "--source-root",
                           str(variant), *map(str, args)],
                          capture_output=True, text=True, cwd=ROOT, timeout=300)


@pytest.mark.parametrize("variant", ["buggy", "clean"])
def test_json_coverage_matches_the_case_and_the_schema(variant: str) -> None:
    case = json.loads((CASE / variant / "case.json").read_text())
    result = check(CASE / variant, "--format", "json")
    assert result.returncode == 0, result.stderr
    document = json.loads(result.stdout)
    jsonschema.validate(document, JSON_SCHEMA)
    coverage = document["coverage"]
    assert {k: coverage[k] for k in ("recovered", "partial", "opaque")} == case["coverage"]
    assert len(coverage["nodes"]) == sum(case["coverage"].values())
    if variant == "clean":
        assert all(n["status"] == "recovered" and n["reasons"] == [] for n in coverage["nodes"])
        return
    nodes = {n["node"]: n for n in coverage["nodes"]}
    assert nodes["/lidar"]["status"] == "opaque" and nodes["/lidar"]["origin"] == ""
    assert nodes["/lidar"]["reasons"] == [{"message": "no model or source for vendor_lidar/lidar_driver",
                                           "file": "src/relay/launch/relay.launch", "line": 4}]
    assert nodes["/scan_relay"]["status"] == "partial" and nodes["/scan_relay"]["origin"] == "python"
    assert nodes["/scan_relay"]["reasons"] == [{"message": "publisher name unknown: pathlib.Path('/etc/relay_topic').read_text()",
                                                "file": "src/relay/scripts/scan_relay.py", "line": 10}]
    assert nodes["/scan_source"]["status"] == "recovered"
    # the call that created the port gets a note naming what is unknown
    notes = [d for d in document["diagnostics"] if d["code"] == "port-name-unknown"]
    assert [(d["file"], d["line"], d["severity"]) for d in notes] == [("src/relay/scripts/scan_relay.py", 10, "note")]
    assert "pathlib.Path('/etc/relay_topic').read_text()" in notes[0]["message"]


def test_text_prints_the_recovery_block_after_the_summary() -> None:
    lines = check(CASE / "buggy").stdout.splitlines()
    at = next(i for i, line in enumerate(lines) if line.startswith("0 findings"))
    assert lines[at + 1] == "recovery: 1 of 3 nodes fully recovered, 1 partial, 1 opaque (no model or source)"
    assert lines[at + 2:] == [
        "  opaque /lidar: no model or source for vendor_lidar/lidar_driver (src/relay/launch/relay.launch:4)",
        "  partial /scan_relay: publisher name unknown: pathlib.Path('/etc/relay_topic').read_text() "
        "(src/relay/scripts/scan_relay.py:10)"]
    clean = check(CASE / "clean", "--quiet").stdout.splitlines()
    assert clean[-1] == "recovery: 2 of 2 nodes fully recovered, 0 partial, 0 opaque (no model or source)"


@pytest.mark.parametrize("variant", ["buggy", "clean"])
def test_sarif_coverage_notifications_validate(variant: str, sarif_schema: dict) -> None:
    sarif = json.loads(check(CASE / variant, "--format", "sarif").stdout)
    jsonschema.validate(sarif, sarif_schema)
    invocation = sarif["runs"][0]["invocations"][0]
    counts = json.loads((CASE / variant / "case.json").read_text())["coverage"]
    assert invocation["properties"]["coverage"] == counts
    coverage = {(n["descriptor"]["id"], n["properties"]["node"],
                 n["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
                 n["locations"][0]["physicalLocation"]["region"]["startLine"])
                for n in invocation["toolExecutionNotifications"] if n["descriptor"]["id"].startswith("recovery-")}
    expected = {("recovery-opaque", "/lidar", "src/relay/launch/relay.launch", 4),
                ("recovery-partial", "/scan_relay", "src/relay/scripts/scan_relay.py", 10)}
    assert coverage == (expected if variant == "buggy" else set())


def test_fail_on_incomplete() -> None:
    assert check(CASE / "buggy").returncode == 0
    assert check(CASE / "buggy", "--fail-on-incomplete", "--format", "json").returncode == 1
    assert check(CASE / "clean", "--fail-on-incomplete").returncode == 0
    assert check(CASE / "buggy", "--fail-on-incomplete", "--fail-on", "never").returncode == 1


def test_diff_divides_both_approximations_by_the_observed_count() -> None:
    observed = Architecture(frozenset({"/a", "/b"}), frozenset({("/a", "/x", "T"), ("/a", "/y", "T")}),
                            frozenset(), frozenset())
    recovered = Architecture(frozenset({"/a", "/b", "/c", "/d", "/e"}),
                             frozenset({("/a", "/x", "T"), ("/a", "/z", "T"), ("/a", "/w", "T")}),
                             frozenset(), frozenset())
    table = compare(recovered, observed)
    # nodes: 3 extra over 2 observed (the old code divided by the 5 recovered: 60.0)
    assert table["nodes"]["over_approximation"] == 150.0 and table["nodes"]["under_approximation"] == 0.0
    assert table["publishers"]["over_approximation"] == 100.0  # 2 extra / 2 observed, not 2/3
    assert table["publishers"]["under_approximation"] == 50.0
    assert table["subscribers"]["over_approximation"] == table["subscribers"]["under_approximation"] == 0.0


def test_a_macro_that_drops_its_argument_does_not_stop_the_nesting_check() -> None:
    # `#define DROP(x) 0` copies its argument 0 times: the check divided by it (ZeroDivisionError,
    # which stopped the analysis of husky and turtlebot in bench/eval_recovery.py)
    from archlog.extract.cpp.macros import defines, nested_calls

    path = Path("m.cpp")
    text = "#define DROP(x) 0\n#define F(x) x x\nint a = DROP(F(1)) + F(2);\nint b = " + "F(" * 40 + "1" + ")" * 40 + ";\n"
    assert nested_calls([(path, text[: text.index("int b")])], defines(path, text)) is None
    assert nested_calls([(path, text)], defines(path, text)) == (path, 4, "F")


def package(root: Path, name: str, buildtool: str) -> Path:
    """A package `name` under root/src with a launch folder."""
    pkg = root / "src" / name
    (pkg / "launch").mkdir(parents=True)
    (pkg / "package.xml").write_text(f"<package format='3'><name>{name}</name><version>1.0.0</version>"
                                     "<description>d</description><maintainer email='a@example.com'>a</maintainer>"
                                     f"<license>MIT</license><buildtool_depend>{buildtool}</buildtool_depend>"
                                     "</package>\n")
    return pkg


def checker(root: Path, launch: str) -> Callable[..., subprocess.CompletedProcess]:
    """`archlog check ROOT --launch LAUNCH --source-root ROOT ARGS...`."""
    return lambda *args: subprocess.run([sys.executable, "-m", "archlog", "check", str(root), "--launch", launch,
                                         "--source-root", str(root), *args],
                                        capture_output=True, text=True, cwd=ROOT, timeout=300)


def test_a_launch_part_not_read_makes_the_report_partial(tmp_path: Path) -> None:
    # a while loop, an include of a missing file, and an action whose value is not known: each one
    # is counted in the recovery summary at its file:line, and --fail-on-incomplete fails on them
    pkg = package(tmp_path, "bringup", "ament_cmake")
    (pkg / "launch" / "holes.launch.py").write_text(
        "import os\n"
        "from launch import LaunchDescription\n"
        "from launch.actions import IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "def generate_launch_description():\n"
        "    actions = []\n"
        "    while len(actions) < 2:\n"
        "        actions.append(None)\n"
        "    return LaunchDescription([\n"
        "        IncludeLaunchDescription(PythonLaunchDescriptionSource('/nowhere/missing.launch.py')),\n"
        "    ])\n")
    launch = "src/bringup/launch/holes.launch.py"
    run = checker(tmp_path, "bringup/launch/holes.launch.py")
    document = json.loads(run("--format", "json").stdout)
    jsonschema.validate(document, JSON_SCHEMA)
    holes = document["coverage"]["holes"]
    assert [(h["file"], h["line"]) for h in holes] == [(launch, 7), (launch, 10)]
    assert "while loop" in holes[0]["message"] and "missing.launch.py" in holes[1]["message"]
    text = run().stdout
    assert "2 parts of the configuration not read" in text
    assert f"not read: {holes[0]['message']} ({launch}:7)" in text
    assert run("--fail-on", "never").returncode == 0
    assert run("--fail-on", "never", "--fail-on-incomplete").returncode == 1


def test_a_ros1_include_skipped_makes_the_report_partial(tmp_path: Path) -> None:
    # an <include> of a package that is not in the workspace (roslaunch would fail on this machine
    # too): the report is partial at the include's file:line, with a hint that can fix the cause;
    # an include of a package that is here is read and leaves no hole
    pkg = package(tmp_path, "sim", "catkin")
    (pkg / "launch" / "inner.launch").write_text("<launch>\n  <param name='x' value='1'/>\n</launch>\n")
    (pkg / "launch" / "world.launch").write_text(
        "<launch>\n"
        "  <include file=\"$(find sim)/launch/inner.launch\"/>\n"
        "  <include file=\"$(find absent_world_pkg)/launch/empty.launch\">\n"
        "    <arg name=\"paused\" value=\"true\"/>\n"
        "  </include>\n"
        "</launch>\n")
    launch = "src/sim/launch/world.launch"
    run = checker(tmp_path, "sim/launch/world.launch")
    document = json.loads(run("--format", "json").stdout)
    jsonschema.validate(document, JSON_SCHEMA)
    holes = document["coverage"]["holes"]
    assert [(h["file"], h["line"]) for h in holes] == [(launch, 3)]
    assert "package 'absent_world_pkg' not found" in holes[0]["message"]
    assert "add the folder of package absent_world_pkg to the analysed paths" in holes[0]["message"]
    assert "--arg" not in holes[0]["message"]
    assert "1 part of the configuration not read" in run().stdout
    sarif = json.loads(run("--format", "sarif").stdout)
    assert any("absent_world_pkg" in str(n) for n in sarif["runs"][0]["invocations"][0].get(
        "toolExecutionNotifications", [])), sarif["runs"][0]["invocations"]
    assert run("--fail-on", "never").returncode == 0
    assert run("--fail-on", "never", "--fail-on-incomplete").returncode == 1
