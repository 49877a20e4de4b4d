"""ruff/catkin_lint habits: --select/--ignore/--extend-select (the mechanism of archlog.toml's
select/ignore), `archlog rule ID`, named systems (`--system NAME`), operator tools declared in
archlog.toml, and every option of every command described in the docs."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import click
import pytest
from conftest import CORPUS, ROOT

from archlog.cli import main

BUGGY = CORPUS / "topic_typo" / "buggy"
LAUNCH = ["--launch", "waypoint_nav/launch/follow_waypoints.launch"]
OPERATOR = CORPUS / "operator_goal"


def archlog(*args: str | Path, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, timeout=300)


def rules_found(*args: str | Path, cwd: Path = ROOT) -> list[str]:
    result = archlog("check", *args, "--format", "json", "--fail-on", "never", cwd=cwd)
    assert result.returncode == 0, result.stderr
    return [f["rule"] for f in json.loads(result.stdout)["findings"]]


def test_select_ignore_and_extend_select_take_ids_prefixes_and_tags(tmp_path: Path) -> None:
    assert rules_found(BUGGY, *LAUNCH) == ["AL102"]
    assert rules_found(BUGGY, *LAUNCH, "--ignore", "AL102") == []
    assert rules_found(BUGGY, *LAUNCH, "--ignore", "names") == []  # a tag of AL102
    assert rules_found(BUGGY, *LAUNCH, "--select", "AL2,AL3") == []
    assert rules_found(BUGGY, *LAUNCH, "--select", "AL2", "--select", "near-miss-topic") == ["AL102"]
    # the command line and archlog.toml are one mechanism: --select replaces the file's select,
    # --extend-select adds to it, --ignore adds to its ignore
    ws = tmp_path / "ws"
    shutil.copytree(BUGGY, ws)
    (ws / "archlog.toml").write_text('select = ["AL2"]\n')
    assert rules_found(ws, *LAUNCH) == []
    assert rules_found(ws, *LAUNCH, "--extend-select", "AL1") == ["AL102"]
    assert rules_found(ws, *LAUNCH, "--select", "topics") == ["AL102"]
    assert rules_found(ws, *LAUNCH, "--select", "topics", "--ignore", "AL10") == []


def test_select_and_ignore_take_diagnostic_codes(tmp_path: Path) -> None:
    ws = tmp_path / "ws"
    shutil.copytree(BUGGY, ws)
    (ws / "src" / "waypoint_nav" / "launch" / "broken.launch").write_text("<launch>\n  <node pkg='x'\n</launch>\n")
    args = [ws, *LAUNCH, "--launch", "waypoint_nav/launch/broken.launch", "--format", "json"]
    codes = {d["code"] for d in json.loads(archlog("check", *args).stdout)["diagnostics"]}
    assert "launch-xml" in codes
    ignored = {d["code"] for d in json.loads(archlog("check", *args, "--ignore", "launch-").stdout)["diagnostics"]}
    assert not any(code.startswith("launch-") for code in ignored)


def test_a_pattern_that_names_nothing_is_a_usage_error() -> None:
    result = archlog("check", BUGGY, *LAUNCH, "--select", "AL9")
    assert result.returncode == 2 and "'AL9' names no rule id, name or tag" in result.stderr


def test_rule_explains_description_example_and_fix() -> None:
    result = archlog("rule", "AL102")
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert out.startswith("AL102 near-miss-topic (error; a note when what archlog could not read may hold the "
                          "counterpart, precision medium; tags: topics, names, dangling)\n")
    assert "A subscriber with no publisher waits forever" in out  # the description
    assert "Example finding (from the rule's fixtures):\n  ctl.cpp:11 /arm/joint_cmd: /arm/ctl subscribes" in out
    assert 'How to fix:\nConnect them in the launch file: `<remap from="TOPIC" to="OTHER_TOPIC"/>`' in out
    assert out.rstrip().endswith("docs/rules.md#al102")
    assert archlog("rule", "near-miss-topic").stdout == out  # by name too
    listed = archlog("rule").stdout.splitlines()
    assert len(listed) >= 15 and listed[0].startswith("AL101   error    topic-type-mismatch: ")
    wrong = archlog("rule", "AL1O2")
    assert wrong.returncode == 2 and "no rule 'AL1O2'; did you mean AL102" in wrong.stderr


def test_rule_explains_a_team_rule_from_the_configuration(tmp_path: Path) -> None:
    shutil.copytree(ROOT / "docs" / "examples" / "rules", tmp_path / "team_rules")
    (tmp_path / "archlog.toml").write_text('rules = ["team_rules/"]\n')
    out = archlog("rule", "EX001", cwd=tmp_path).stdout
    assert out.startswith("EX001 several-publishers") and "How to fix:" in out
    assert "More:" not in out  # a rule without `url` links nowhere


def test_named_system_runs_from_archlog_toml(tmp_path: Path) -> None:
    ws = tmp_path / "robot"
    shutil.copytree(BUGGY, ws / "ws")
    (ws / "archlog.toml").write_text('[systems.nav]\npaths = ["ws"]\n'
                                     'launch = ["waypoint_nav/launch/follow_waypoints.launch"]\n')
    assert rules_found("--system", "nav", cwd=ws) == ["AL102"]
    unknown = archlog("check", "--system", "navv", cwd=ws)
    assert unknown.returncode == 2 and "unknown system 'navv' (known: nav)" in unknown.stderr
    assert rules_found(cwd=ws) == ["AL102"]  # no PATH: the one named system (a pre-commit hook without args)
    (ws / "archlog.toml").write_text('[systems.nav]\npaths = ["ws"]\nlaunchs = []\n')
    bad = archlog("check", "--system", "nav", cwd=ws)
    assert bad.returncode == 2 and "[systems.nav]: unknown key(s) launchs" in bad.stderr


def test_named_system_args_models_and_the_command_line(tmp_path: Path) -> None:
    shutil.copytree(CORPUS / "include_missing_remap" / "buggy", tmp_path / "ws")
    (tmp_path / "archlog.toml").write_text(
        '[systems.guard]\npaths = ["ws"]\n'
        'launch = ["laser_bringup/launch/laser.launch", "safety_monitor/launch/guard.launch"]\n'
        'args = {scan_topic = "base_scan"}\n')
    assert rules_found("--system", "guard", cwd=tmp_path) == []
    assert rules_found("--system", "guard", "--arg", "scan_topic:=scan", cwd=tmp_path) == ["AL601"]  # --arg wins
    (tmp_path / "scan.yaml").write_text("instance: /replay\npublishers:\n  - {name: /scan, type: sensor_msgs/LaserScan}\n")
    (tmp_path / "archlog.toml").write_text(
        'operators = ["rviz"]\n[systems.guard]\npaths = ["ws"]\nlaunch = ["safety_monitor/launch/guard.launch"]\n'
        'models = ["scan.yaml"]\noperators = ["rviz"]\n')
    assert rules_found("--system", "guard", cwd=tmp_path) == []  # the model feeds /scan; rviz is one instance


def test_named_system_of_a_workspace_config_stays_in_its_folder(tmp_path: Path) -> None:
    shutil.copytree(BUGGY, tmp_path / "robot" / "ws")
    (tmp_path / "robot" / "archlog.toml").write_text('[systems.nav]\npaths = ["../elsewhere"]\n')
    (tmp_path / "elsewhere").mkdir()
    result = archlog("check", "robot/ws", "--system", "nav", cwd=tmp_path)
    assert result.returncode == 2 and "outside" in result.stderr


def test_operator_tools_feed_the_goal(tmp_path: Path) -> None:
    launch = ["--launch", "goal_runner/launch/runner.launch"]
    assert rules_found(OPERATOR / "clean", *launch) == []  # its archlog.toml: operators = ["rviz"]
    undeclared = tmp_path / "clean"
    shutil.copytree(OPERATOR / "clean", undeclared)
    (undeclared / "archlog.toml").unlink()
    assert rules_found(undeclared, *launch) == ["AL601"]  # the goal from RViz is unknown without it
    (undeclared / "archlog.toml").write_text('operators = ["rviz", "teleop"]\n')
    # an operator's ports are checked like any other: teleop's /cmd_vel reaches nobody (the base
    # listens on /robot1/cmd_vel), a near miss
    result = archlog("check", undeclared, *launch, "--format", "json", "--fail-on", "never")
    [finding] = json.loads(result.stdout)["findings"]
    assert finding["rule"] == "AL102" and finding["subjects"]["nodes"] == ["/operator/teleop", "/robot1/base_driver"]
    (undeclared / "archlog.toml").write_text('operators = ["rvis"]\n')
    result = archlog("check", undeclared, *launch)
    assert result.returncode == 2 and "unknown operator tool 'rvis'" in result.stderr


def _options() -> list[str]:
    names = []
    for command in main.commands.values():
        names += [opt for param in command.params if isinstance(param, click.Option) for opt in param.opts
                  if opt.startswith("--") and opt != "--help"]
    return sorted(set(names))


@pytest.mark.parametrize("option", _options())
def test_docs_describe_every_option(option: str) -> None:
    docs = "\n".join(p.read_text() for p in [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))])
    assert re.search(rf"`[^`\n]*{re.escape(option)}\b", docs), f"no page of docs/ or README.md describes {option}"


def test_models_page_examples_follow_the_schema_and_name_every_key() -> None:
    import jsonschema
    import yaml

    page = (ROOT / "docs" / "models.md").read_text()
    schema = json.loads((ROOT / "archlog" / "models" / "model.schema.json").read_text())
    examples = re.findall(r"```yaml\n(.*?)```", page, re.S)
    assert len(examples) >= 4
    for example in examples:
        jsonschema.validate(yaml.safe_load(example), schema)
    keys = {key for definition in schema["$defs"].values() for key in definition.get("properties", {})}
    keys |= {key for option in schema["$defs"]["qos"]["oneOf"] for key in option.get("properties", {})}
    assert keys >= {"instance", "incomplete", "each", "liveliness_lease_duration"}
    assert [key for key in sorted(keys) if f"`{key}`" not in page and f"{key}:" not in page] == []
    for tool in sorted(p.stem for p in (ROOT / "archlog" / "models" / "operators").glob("*.yaml")):
        assert f"| `{tool}` |" in page
