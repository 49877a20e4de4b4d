"""The CLI contract: formats, exit codes, SARIF/JSON validity, bad input never shows a traceback."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import jsonschema
import pytest
from conftest import CORPUS, ROOT

BUGGY = CORPUS / "topic_typo" / "buggy"
CLEAN = CORPUS / "topic_typo" / "clean"
JSON_SCHEMA = json.loads((ROOT / "archlog" / "reports" / "findings.schema.json").read_text())


def archlog(*args: str | Path, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, timeout=300)


def launch_of(variant: Path) -> list[str]:
    case = json.loads((variant / "case.json").read_text())
    return [w for spec in case["launch"] for w in ("--launch", spec)]


def test_exit_status_follows_fail_on() -> None:
    assert archlog("check", BUGGY, *launch_of(BUGGY)).returncode == 1
    assert archlog("check", BUGGY, *launch_of(BUGGY), "--fail-on", "never").returncode == 0
    assert archlog("check", CLEAN, *launch_of(CLEAN)).returncode == 0
    assert archlog("check", CLEAN, *launch_of(CLEAN), "--fail-on", "note").returncode == 0


@pytest.mark.parametrize("args", [
    ["check", "no/such/dir"],
    ["check", str(CLEAN), "--launch", "nope/missing.launch"],
    ["check", str(CLEAN), "--arg", "no_equals_sign"],
    ["check", str(CLEAN), "--format", "xml"],
    ["check", str(CLEAN), "--model", "missing.yaml"],
])
def test_usage_and_configuration_errors_exit_2(args: list[str]) -> None:
    result = archlog(*args)
    assert result.returncode == 2, result.stderr
    assert "Traceback" not in result.stderr and result.stderr.strip()


def test_broken_user_rule_exits_2_with_location(tmp_path: Path) -> None:
    rule = tmp_path / "bad.lp"
    rule.write_text("%! id: X1\n%! name: x\n%! severity: note\n%! summary: s\n%! finding: x(topic, p)\n"
                    "%! location: p\n%! message: m\nx(T, P) :- publisher(P, _, T, _), nope(T).\n")
    result = archlog("check", CLEAN, *launch_of(CLEAN), "--rules", rule)
    assert result.returncode == 2
    assert f"{rule}:8:" in result.stderr and "unknown relation nope/1" in result.stderr


def test_json_report_matches_documented_schema() -> None:
    result = archlog("check", BUGGY, *launch_of(BUGGY), "--format", "json")
    document = json.loads(result.stdout)
    jsonschema.validate(document, JSON_SCHEMA)
    [finding] = document["findings"]
    assert finding["rule"] == "AL102" and finding["subjects"]["topics"] == ["/rover/base_waypoint", "/rover/base_waypoints"]
    assert [loc["role"] for loc in finding["locations"]] == ["primary", "related"]
    assert all(loc["line"] > 0 for loc in finding["locations"])


def test_sarif_validates_against_the_official_schema(tmp_path: Path, sarif_schema: dict) -> None:
    out = tmp_path / "report.sarif"
    assert archlog("check", BUGGY, *launch_of(BUGGY), "--format", "sarif", "--output", out).returncode == 1
    sarif = json.loads(out.read_text())
    jsonschema.validate(sarif, sarif_schema)
    run = sarif["runs"][0]
    assert {r["id"] for r in run["tool"]["driver"]["rules"]} >= {"AL101", "AL102", "AL201", "AL401"}
    [result] = run["results"]
    assert result["ruleId"] == "AL102" and result["relatedLocations"]
    assert result["locations"][0]["physicalLocation"]["artifactLocation"]["uriBaseId"] == "SRCROOT"


def test_a_finding_an_unread_part_may_answer_is_a_note_in_every_report(tmp_path: Path) -> None:
    workspace = tmp_path / "ws"
    shutil.copytree(CORPUS / "service_mismatch" / "buggy", workspace)
    launch = workspace / "src" / "mission_control" / "launch" / "navigation.launch"
    launch.write_text(launch.read_text().replace('<group ns="nav">', '<group ns="nav">\n'
                                                 '    <include file="$(find planning_servers)/launch/servers.launch"/>'))
    args = ["check", workspace, *launch_of(workspace)]
    result = archlog(*args, "--format", "json")
    assert result.returncode == 0, result.stderr
    [finding] = json.loads(result.stdout)["findings"]
    assert finding["rule"] == "AL201" and finding["severity"] == "note"
    assert "not read at src/mission_control/launch/navigation.launch:6 starts its server" in finding["message"]
    sarif = json.loads(archlog(*args, "--format", "sarif").stdout)
    assert [r["level"] for r in sarif["runs"][0]["results"]] == ["note"]
    assert archlog(*args, "--fail-on", "note").returncode == 1
    assert "0 errors" in archlog(*args, "--quiet").stdout


def test_bad_input_gives_diagnostics_in_every_format(tmp_path: Path, sarif_schema: dict) -> None:
    pkg = tmp_path / "src" / "messy"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "launch").mkdir()
    (pkg / "package.xml").write_text("<package format='2'><name>messy</name><version>0.0.1</version>"
                                     "<description>d</description><maintainer email='dev@example.com'>m</maintainer>"
                                     "<license>MIT</license></package>")
    (pkg / "CMakeLists.txt").write_text("project(messy)\nadd_executable(broken_node src/missing.cpp)\n")
    for name, text in {"old.py": "#!/usr/bin/env python\nimport rospy\nprint 'hi'\n",
                       "good.py": "#!/usr/bin/env python3\nimport rospy\nfrom std_msgs.msg import String\n"
                                  "rospy.init_node('good')\nrospy.Publisher('out', String)\n"}.items():
        (pkg / "scripts" / name).write_text(text)
        (pkg / "scripts" / name).chmod(0o755)
    (pkg / "launch" / "all.launch").write_text(
        "<launch>\n  <include file='$(find messy)/launch/nope.launch'/>\n"
        "  <node pkg='unknown_pkg_zz' type='x' name='ghost'/>\n  <node pkg='messy' type='old.py' name='old'/>\n"
        "  <node pkg='messy' type='good.py' name='good'/>\n  <node pkg='messy' type='broken_node' name='b'/>\n"
        "  <node pkg='$(find nowhere_pkg)' type='x' name='y'/>\n</launch>\n")
    (pkg / "launch" / "bad.launch").write_text("<launch>\n  <node pkg='messy' type='good.py'\n</launch>\n")
    json_out = archlog("check", tmp_path, "--launch", "messy/launch/all.launch", "--launch", "messy/launch/bad.launch",
                       "--format", "json")
    assert "Traceback" not in json_out.stderr
    diags = {(d["file"], d["line"], d["code"]) for d in json.loads(json_out.stdout)["diagnostics"]}
    assert ("src/messy/launch/all.launch", 2, "launch-include") in diags
    assert ("src/messy/launch/all.launch", 3, "no-model") in diags
    assert ("src/messy/scripts/old.py", 3, "python2") in diags
    assert ("src/messy/src/missing.cpp", 1, "cpp-missing") in diags
    assert ("src/messy/launch/all.launch", 7, "launch-unresolved") in diags
    assert any(f == "src/messy/launch/bad.launch" and c == "launch-xml" for f, _l, c in diags)
    sarif = json.loads(archlog("check", tmp_path, "--launch", "messy/launch/all.launch", "--format", "sarif").stdout)
    jsonschema.validate(sarif, sarif_schema)
    notes = sarif["runs"][0]["invocations"][0]["toolExecutionNotifications"]
    assert {n["descriptor"]["id"] for n in notes} >= {"launch-include", "no-model", "python2", "cpp-missing"}
    text = archlog("check", tmp_path, "--launch", "messy/launch/all.launch")
    assert "Traceback" not in text.stdout + text.stderr and "python2" in text.stdout


def test_text_report_shows_both_sides_with_source() -> None:
    out = archlog("check", BUGGY, *launch_of(BUGGY)).stdout
    assert "AL102" in out and "base_waypoint" in out and "other side:" in out
    assert 'nh.subscribe("base_waypoint"' in out and "^" in out
    assert "1 finding (1 error, 0 warnings, 0 notes)" in out


def test_facts_export_writes_every_relation(tmp_path: Path) -> None:
    from archlog.facts.schema import RELATIONS

    for fmt in ("csv", "json"):
        result = archlog("facts", BUGGY, *launch_of(BUGGY), "--format", fmt, tmp_path / fmt)
        assert result.returncode == 0, result.stderr
        assert {p.stem for p in (tmp_path / fmt).iterdir()} == {r.name for r in RELATIONS}
    subs = json.loads((tmp_path / "json" / "subscriber.json").read_text())
    assert {"port", "node", "topic", "type"} == set(subs[0])
    assert any(s["topic"] == "/rover/base_waypoint" for s in subs)
    assert (tmp_path / "csv" / "publisher.csv").read_text().startswith("port,node,topic,type\n")


def test_rosrun_configuration_without_launch() -> None:
    result = archlog("check", CLEAN, "--format", "json", "--fail-on", "never")
    document = json.loads(result.stdout)
    assert result.returncode == 0 and isinstance(document["findings"], list)


def test_sarif_names_the_launch_include_chain_of_each_node(sarif_schema: dict) -> None:
    variant = CORPUS / "include_missing_remap" / "buggy"
    sarif = json.loads(archlog("check", variant, *launch_of(variant), "--format", "sarif", "--fail-on", "never").stdout)
    jsonschema.validate(sarif, sarif_schema)
    related = [(r["message"]["text"], r["physicalLocation"]["artifactLocation"]["uri"])
               for r in sarif["runs"][0]["results"][0]["relatedLocations"]]
    # AL601 at proximity_guard, declared in guard.launch, which robot.launch includes; paths are
    # relative to the repository holding the corpus (the git work tree of the first PATH)
    where = variant.relative_to(ROOT).as_posix()
    assert ("node /proximity_guard is declared here", f"{where}/src/safety_monitor/launch/guard.launch") in related
    assert ("included from here (level 1)", f"{where}/src/safety_monitor/launch/robot.launch") in related
