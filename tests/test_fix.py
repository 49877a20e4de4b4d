"""`archlog check --fix`, `--unsafe-fixes` and `--diff` on copies of corpus buggy twins: the fixed
workspace checks clean; fix hints use the finding's own names for every rule."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import CORPUS, CORPUS_ROS2, load_case

from archlog.reports.fixes import _python_remap, _rename, _xml_remap
from archlog.reports.rule_help import hint
from archlog.rules.ruleset import RuleError, load_rules


def archlog(*args: str | Path, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, timeout=300)


def copy(variant: Path, tmp: Path) -> tuple[Path, list[str]]:
    """A copy of the variant, and the check arguments of its case."""
    shutil.copytree(variant, tmp / "ws")
    return tmp / "ws", ["check", "src", *[a for launch in load_case(variant)["launch"] for a in ("--launch", launch)]]


def findings(ws: Path, check: list[str]) -> list[dict]:
    result = archlog(*check, "--format", "json", "--fail-on", "never", cwd=ws)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)["findings"]


def test_fix_applies_the_safe_remap_and_the_check_is_clean(tmp_path: Path) -> None:
    ws, check = copy(CORPUS / "topic_typo" / "buggy", tmp_path)
    assert [f["rule"] for f in findings(ws, check)] == ["AL102"]
    launch = ws / "src/waypoint_nav/launch/follow_waypoints.launch"
    before = launch.read_text()
    shown = archlog(*check, "--diff", cwd=ws)
    assert shown.returncode == 1 and launch.read_text() == before  # --diff writes nothing
    assert '+      <remap from="/rover/base_waypoint" to="/rover/base_waypoints"/>' in shown.stdout
    fixed = archlog(*check, "--fix", cwd=ws)
    assert fixed.returncode == 0, fixed.stdout + fixed.stderr
    assert "applied 1 fix in 1 file" in fixed.stderr and "0 findings" in fixed.stdout
    assert findings(ws, check) == []
    assert archlog(*check, "--diff", cwd=ws).stdout == ""  # nothing left to fix


@pytest.mark.parametrize("variant", [CORPUS / "spawner_param_file" / "buggy", CORPUS_ROS2 / "spawner_param_file" / "buggy"],
                         ids=["ros1-xml", "ros2-python"])
def test_unsafe_fix_needs_unsafe_fixes(variant: Path, tmp_path: Path) -> None:
    ws, check = copy(variant, tmp_path)
    safe = archlog(*check, "--fix", cwd=ws)
    assert "applied 0 fixes in 0 files; 1 more with --unsafe-fixes" in safe.stderr
    assert [f["rule"] for f in findings(ws, check)] == ["AL103"]
    unsafe = archlog(*check, "--fix", "--unsafe-fixes", cwd=ws)
    assert "applied 1 fix in 1 file" in unsafe.stderr, unsafe.stderr
    assert findings(ws, check) == []


@pytest.mark.parametrize("variant", [CORPUS / "param_name_typo", CORPUS_ROS2 / "param_name_typo_py",
                                     CORPUS_ROS2 / "param_name_typo_cpp"], ids=["ros1-xml", "ros2-yaml", "ros2-python"])
def test_fix_renames_the_parameter_to_the_declared_one(variant: Path, tmp_path: Path) -> None:
    """AL403's fix renames the misspelled parameter where it is set (a <param>, a parameter file's
    key, a parameters= dictionary): the fixed buggy twin is its clean twin, and checks clean."""
    ws, check = copy(variant / "buggy", tmp_path)
    assert "AL403" in [f["rule"] for f in findings(ws, check)]
    fixed = archlog(*check, "--fix", cwd=ws)
    assert "applied 1 fix in 1 file" in fixed.stderr and "fixed: AL403 rename" in fixed.stderr, fixed.stderr
    assert findings(ws, check) == load_case(variant / "clean")["findings"] == []
    clean = variant / "clean" / "src"
    assert {p.relative_to(clean): p.read_bytes() for p in clean.rglob("*") if p.is_file()} == \
        {p.relative_to(ws / "src"): p.read_bytes() for p in (ws / "src").rglob("*") if p.is_file()}


def test_a_rename_edits_one_written_name_in_its_namespace_only() -> None:
    yaml = "a:\n  ros__parameters:\n    scan_topc: scan_topc_x\n"
    start, end, text = _rename(yaml, 3, "scan_topc", "scan_topic")
    assert yaml[:start] + text + yaml[end:] == "a:\n  ros__parameters:\n    scan_topic: scan_topc_x\n"
    assert _rename('<param name="~gain" value="1"/>\n', 1, "~gain", "~gains") == (14, 18, "gains")
    assert _rename('{"gain": "gain"}\n', 1, "gain", "gains") is None  # written twice: which one?
    assert _rename('<param name="pid/gain"/>\n', 1, "pid/gain", "other/gain") is None  # another namespace
    assert _rename("x\n", 5, "x", "y") is None


def test_xml_and_python_edits_keep_the_element_whole() -> None:
    xml = '<launch>\n  <node pkg="a" type="b" name="c"\n        args="x > y" />\n</launch>\n'
    start, end, text = _xml_remap(xml, 3, "/in", "/out&")
    assert xml[:start] + text + xml[end:] == ('<launch>\n  <node pkg="a" type="b" name="c"\n        args="x > y">\n'
                                              '    <remap from="/in" to="/out&amp;"/>\n  </node>\n</launch>\n')
    py = 'Node(package="a",\n     remappings=[("x", "y")],\n)\n'
    start, end, text = _python_remap(py, 1, "/in", "/out")
    assert py[:start] + text + py[end:] == 'Node(package="a",\n     remappings=[("/in", "/out"), ("x", "y")],\n)\n'
    py = 'Node(package="a", executable="b",)\n'
    start, end, text = _python_remap(py, 1, "/in", "/out")
    assert py[:start] + text + py[end:] == 'Node(package="a", executable="b", remappings=[("/in", "/out")])\n'
    assert _python_remap('Node(remappings=computed)\n', 1, "/in", "/out") is None


def test_every_hint_is_built_from_the_findings_names() -> None:
    for rule in load_rules([]).rules:
        values = {c: f"<{c}-value>" for c in [*rule.columns, *rule.lists]}
        text = hint(rule, values)
        assert re.search(r"<\w+-value>", text), f"{rule.id}: its fix hint names nothing of the finding: {text}"
        assert not re.search(r"\{\w+\}", text), text


def test_a_malformed_fix_is_an_error_at_its_line(tmp_path: Path) -> None:
    rule = tmp_path / "x.lp"
    rule.write_text('%! id: X1\n%! name: x\n%! severity: note\n%! summary: s\n%! finding: f(topic, node)\n'
                    '%! location: node\n%! message: "{topic}"\n%! fix: {remap: [node, topic, other], safe: true}\n'
                    'f(T, N) :- publisher(_, N, T, _).\n')
    with pytest.raises(RuleError, match=r"x.lp:8:1: `fix` must be"):
        load_rules([rule])
