"""Reports for code review: paths relative to the repository (a workspace nested two levels inside a
git work tree), SARIF messages that link every related location, a rule's help and url, the concise
format, and one source root for every format."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import jsonschema
import pytest
from conftest import CORPUS, ROOT
from support.multitool import MULTITOOL, multitool_problems

VARIANT = CORPUS / "include_missing_remap" / "buggy"  # AL601 with an other side and an include chain
LAUNCH = ["--launch", "safety_monitor/launch/robot.launch"]
SCHEMA = json.loads((ROOT / "archlog" / "reports" / "findings.schema.json").read_text())
NESTED = "robots/fleet"  # the workspace, two levels below the repository's root


def archlog(*args: str | Path, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, timeout=300)


@pytest.fixture(scope="module")
def repo(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A git repository holding the corpus system at robots/fleet."""
    root = tmp_path_factory.mktemp("review") / "repo"
    shutil.copytree(VARIANT, root / NESTED)
    subprocess.run(["git", "init", "-q", str(root)], check=True, timeout=60)
    return root


def sarif_of(repo: Path, *extra: str, cwd: Path = ROOT) -> dict:
    result = archlog("check", repo / NESTED, *LAUNCH, "--format", "sarif", "--fail-on", "never", *extra, cwd=cwd)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def uris(sarif: dict) -> list[str]:
    result = sarif["runs"][0]["results"][0]
    return [loc["physicalLocation"]["artifactLocation"]["uri"]
            for loc in result["locations"] + result["relatedLocations"]]


def test_sarif_paths_are_relative_to_the_git_work_tree(repo: Path, sarif_schema: dict) -> None:
    sarif = sarif_of(repo)  # run from another folder: the root is the repository, not the cwd
    jsonschema.validate(sarif, sarif_schema)
    run = sarif["runs"][0]
    assert run["originalUriBaseIds"]["SRCROOT"]["uri"] == repo.resolve().as_uri() + "/"
    # the finding, then the other side: the candidate publisher of the missing input
    assert uris(sarif) == [f"{NESTED}/src/safety_monitor/scripts/proximity_guard.py",
                           f"{NESTED}/src/laser_bringup/scripts/laser_driver.py",
                           f"{NESTED}/src/safety_monitor/launch/guard.launch",
                           f"{NESTED}/src/safety_monitor/launch/robot.launch"]
    for uri in uris(sarif):  # each names a file of the repository
        assert (repo / uri).is_file()
    assert all(loc["physicalLocation"]["artifactLocation"]["uriBaseId"] == "SRCROOT"
               for loc in run["results"][0]["relatedLocations"])


def test_sarif_message_links_every_related_location(repo: Path) -> None:
    result = sarif_of(repo)["runs"][0]["results"][0]
    links = [int(i) for i in re.findall(r"(?<!\\)\]\((\d+)\)", result["message"]["text"])]
    assert links == [loc["id"] for loc in result["relatedLocations"]] == [1, 2, 3]
    assert "[node /proximity_guard is declared here](2)" in result["message"]["text"]
    assert result["message"]["text"].startswith("/proximity_guard publishes /estop only after it receives /scan")


@pytest.mark.skipif(not MULTITOOL.is_file() and not os.environ.get("CI"),
                    reason="run `npm ci` in tests/sarif-multitool (bash .ci/run does)")
def test_multitool_accepts_sarif_of_a_nested_workspace(repo: Path, tmp_path: Path) -> None:
    out = tmp_path / "nested.sarif"
    out.write_text(json.dumps(sarif_of(repo)))
    assert multitool_problems(out, tmp_path) == []


def test_source_root_overrides_the_work_tree(repo: Path) -> None:
    sarif = sarif_of(repo, "--source-root", str(repo / "robots"))
    assert uris(sarif)[0] == "fleet/src/safety_monitor/scripts/proximity_guard.py"
    assert sarif["runs"][0]["originalUriBaseIds"]["SRCROOT"]["uri"] == (repo / "robots").resolve().as_uri() + "/"


def test_json_and_text_use_the_same_root(repo: Path) -> None:
    document = json.loads(archlog("check", repo / NESTED, *LAUNCH, "--format", "json").stdout)
    jsonschema.validate(document, SCHEMA)
    assert document["root"] == str(repo.resolve())
    [finding] = document["findings"]
    assert [loc["file"] for loc in finding["locations"]] == [f"{NESTED}/src/safety_monitor/scripts/proximity_guard.py",
                                                          f"{NESTED}/src/laser_bringup/scripts/laser_driver.py"]
    text = archlog("check", repo / NESTED, *LAUNCH).stdout
    assert text.startswith(f"{NESTED}/src/safety_monitor/scripts/proximity_guard.py\n")
    assert "rospy.Subscriber(" in text  # the source line is still found from the new root


def test_without_git_the_current_folder_is_the_root(tmp_path: Path) -> None:
    shutil.copytree(VARIANT, tmp_path / "ws")
    inside = json.loads(archlog("check", "ws", *LAUNCH, "--format", "json", cwd=tmp_path).stdout)
    assert inside["root"] == str(tmp_path.resolve())
    assert inside["findings"][0]["locations"][0]["file"] == "ws/src/safety_monitor/scripts/proximity_guard.py"
    elsewhere = json.loads(archlog("check", tmp_path / "ws", *LAUNCH, "--format", "json", cwd=ROOT).stdout)
    assert elsewhere["findings"][0]["locations"][0]["file"] == "src/safety_monitor/scripts/proximity_guard.py"


def test_text_and_json_give_the_fix_hint_and_url(repo: Path) -> None:
    text = archlog("check", repo / NESTED, *LAUNCH).stdout
    [finding] = json.loads(archlog("check", repo / NESTED, *LAUNCH, "--format", "json").stdout)["findings"]
    topic = finding["subjects"]["topics"][0]  # the hint names the finding's own input
    assert f"    fix: Publish {topic}: start the node that provides it" in text
    assert finding["help"].startswith(f"Publish {topic}:") and "\n" not in finding["help"]
    assert finding["url"].endswith("/docs/rules.md#al601")


def test_concise_lines_are_relative_to_the_current_folder(repo: Path) -> None:
    result = archlog("check", NESTED, *LAUNCH, "--format", "concise", cwd=repo)
    assert result.returncode == 1
    assert result.stdout.splitlines()[0].startswith(
        f"{NESTED}/src/safety_monitor/scripts/proximity_guard.py:14:25: AL601 /proximity_guard publishes /estop")
    below = archlog("check", "fleet", *LAUNCH, "--format", "concise", cwd=repo / "robots").stdout
    assert below.startswith("fleet/src/safety_monitor/scripts/proximity_guard.py:14:25: AL601 ")
    above = archlog("check", repo / NESTED, *LAUNCH, "--format", "concise", cwd=repo / NESTED / "src").stdout
    assert above.startswith("safety_monitor/scripts/proximity_guard.py:14:25: AL601 ")


CUSTOM = """%! id: TEAM001
%! name: estop-publisher
%! severity: note
%! summary: A node publishes the emergency stop.
%! finding: estop(topic, pub, node)
%! location: pub
%! message: "{node} publishes {topic}"
%! help: |
%!   Check that the
%!   stop is latched.
%!
%!   More text that is not the hint.
{url}estop(T, P, N) :- publisher(P, N, T, _), T = "/estop".
"""


@pytest.mark.parametrize("url", ["", "https://wiki.example.com/rules/TEAM001"])
def test_custom_rule_gets_help_uri_only_from_its_url(repo: Path, tmp_path: Path, url: str) -> None:
    rule = tmp_path / "team.lp"
    rule.write_text(CUSTOM.replace("{url}", f"%! url: {url}\n" if url else ""))
    sarif = sarif_of(repo, "--rules", str(rule))
    [meta] = [r for r in sarif["runs"][0]["tool"]["driver"]["rules"] if r["id"] == "TEAM001"]
    assert meta.get("helpUri") == (url or None)
    shipped = [r for r in sarif["runs"][0]["tool"]["driver"]["rules"] if r["id"] == "AL601"]
    assert shipped[0]["helpUri"].endswith("docs/rules.md#al601")
    document = json.loads(archlog("check", repo / NESTED, *LAUNCH, "--rules", rule, "--format", "json").stdout)
    [team] = [f for f in document["findings"] if f["rule"] == "TEAM001"]
    assert (team["help"], team["url"]) == ("Check that the stop is latched.", url)


def test_link_text_brackets_are_escaped() -> None:
    from archlog.reports.sarif import _linked
    from archlog.rules.engine import Location

    assert _linked("reads [0] of x", [(Location("a.py", 1), "the other side")]) == \
        "reads \\[0\\] of x (see [the other side](1))"


def test_rebase_finds_each_file_under_the_root_that_holds_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from archlog.reports.paths import Rebase, source_root

    for folder in ("ws_a/src", "ws_b/src", "tools"):
        (tmp_path / folder).mkdir(parents=True)
    (tmp_path / "ws_a" / "src" / "a.py").write_text("")
    (tmp_path / "ws_b" / "src" / "b.py").write_text("")
    (tmp_path / "tools" / "model.yaml").write_text("")
    monkeypatch.chdir(tmp_path / "tools")
    rebase = Rebase([tmp_path / "ws_a", tmp_path / "ws_b"], tmp_path)
    assert [rebase("src/a.py"), rebase("src/b.py"), rebase("model.yaml"), rebase("/opt/x.launch"), rebase("")] == \
        ["ws_a/src/a.py", "ws_b/src/b.py", "tools/model.yaml", "/opt/x.launch", ""]
    assert source_root(tmp_path / "ws_a") == tmp_path / "ws_a"  # no git, outside the current folder
    assert source_root(Path("."), tmp_path) == tmp_path
