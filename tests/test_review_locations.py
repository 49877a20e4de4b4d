"""Every finding's primary location is a file of the analysed repository, in every format: a finding
about a port of a node without source (a shipped YAML model) lands on the user's `<node>` or
`Node(...)`, with the model as a related location. ROS 1 and ROS 2 corpus systems whose hardware
node is taken out, so that the controller spawner's service calls (model ports) go unanswered."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import CORPUS, CORPUS_ROS2

ROS1_LAUNCH = "src/base_bringup/launch/base.launch"
ROS2_LAUNCH = "src/base_control/launch/base.launch.py"


def archlog(*args: str | Path, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, timeout=300)


def repository(tmp: Path, variant: Path, launch: str, drop: str) -> Path:
    """A git work tree holding the corpus system, with the launch line matching `drop` removed."""
    root = tmp / "repo"
    shutil.copytree(variant, root)
    path = root / launch
    text = path.read_text()
    kept = [line for line in text.splitlines(keepends=True) if not re.search(drop, line)]
    assert len(kept) < len(text.splitlines()), drop
    path.write_text("".join(kept))
    subprocess.run(["git", "init", "-q", str(root)], check=True, timeout=60)
    return root


@pytest.fixture(scope="module", params=["ros1", "ros2"])
def system(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, str, set[int]]:
    """(repository, launch file, lines of the spawners' node elements) of a system without hardware node."""
    tmp = tmp_path_factory.mktemp(request.param)
    if request.param == "ros1":
        root = repository(tmp, CORPUS / "spawner_param_file" / "buggy", ROS1_LAUNCH, r'type="base_hw.py"')
        return root, ROS1_LAUNCH, {4}
    root = repository(tmp, CORPUS_ROS2 / "spawner_param_file" / "buggy", ROS2_LAUNCH, r"ros2_control_node|"
                      r"parameters=\[os.path.join\(config, \"controllers.yaml\"\)\]\),")
    return root, ROS2_LAUNCH, {14, 15}  # two spawners


def report(system: tuple[Path, str, set[int]], fmt: str) -> str:
    root, launch, _line = system
    result = archlog("check", root / "src", "--launch", Path(launch).relative_to("src"), "--format", fmt,
                     "--fail-on", "never", cwd=root)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_sarif_primary_locations_are_in_the_repository(system: tuple[Path, str, set[int]]) -> None:
    root, launch, lines = system
    results = json.loads(report(system, "sarif"))["runs"][0]["results"]
    unanswered = [r for r in results if r["ruleId"] == "AL201"]
    # each spawner's calls: ROS 1 load, switch and unload_controller; ROS 2 list, load, configure and switch_controller
    assert len(unanswered) == (4 if launch == ROS2_LAUNCH else 3) * len(lines)
    for result in results:
        primary = result["locations"][0]["physicalLocation"]
        assert primary["artifactLocation"] == {"uri": primary["artifactLocation"]["uri"], "uriBaseId": "SRCROOT"}
        assert (root / primary["artifactLocation"]["uri"]).is_file()
    for result in unanswered:
        primary = result["locations"][0]["physicalLocation"]
        assert primary["artifactLocation"]["uri"] == launch
        assert primary["region"]["startLine"] in lines
        model = result["relatedLocations"][0]
        assert model["physicalLocation"]["artifactLocation"]["uri"].endswith("archlog/models/controller_manager.yaml")
        assert model["message"]["text"].startswith("declared in the model of /")


def test_json_codequality_and_text_use_the_same_place(system: tuple[Path, str, set[int]]) -> None:
    _root, launch, lines = system
    findings = [f for f in json.loads(report(system, "json"))["findings"] if f["rule"] == "AL201"]
    assert {(f["locations"][0]["file"], f["locations"][0]["line"]) for f in findings} == {(launch, n) for n in lines}
    assert all(f["locations"][1]["label"].startswith("declared in the model of") for f in findings)
    quality = [i for i in json.loads(report(system, "codequality")) if i["description"].startswith("AL201")]
    assert {(i["location"]["path"], i["location"]["lines"]["begin"]) for i in quality} == {(launch, n) for n in lines}
    concise = report(system, "concise")
    per_spawner = 4 if launch == ROS2_LAUNCH else 3  # as in the SARIF test above
    assert all(concise.count(f"{launch}:{n}:1: AL201 ") == per_spawner for n in lines)


def test_the_graph_page_shows_the_same_place(system: tuple[Path, str, set[int]]) -> None:
    # the HTML page lists each finding with its file:line (relative to the analysed folder): the user's
    # launch file, not the shipped model
    root, launch, lines = system
    page = root / "graph.html"
    result = archlog("graph", root / "src", "--launch", Path(launch).relative_to("src"), "--output", page, cwd=root)
    assert result.returncode == 0, result.stderr
    places = set(re.findall(r'"where": "([^"]*)"', page.read_text()))
    assert {f"{Path(launch).relative_to('src')}:{n}" for n in lines} <= places
    assert not [p for p in places if "archlog/models/" in p]
