"""`archlog observe` and `archlog diff` end to end: a corpus system runs on a loopback master."""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
from pathlib import Path

import yaml
from conftest import CORPUS, ROOT, load_case, requires_ros
from support.build_cpp import build_workspace
from support.live_graph import running_system

from archlog.analysis import resolve_launch
from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace.index import Workspace

pytestmark = requires_ros()


def archlog(*args: str | Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *map(str, args)], capture_output=True, text=True,
                          cwd=ROOT, timeout=300)


def test_observe_then_diff_is_empty_where_recovery_is_complete(tmp_path: Path) -> None:
    variant = CORPUS / "wrong_remap" / "buggy"
    case = load_case(variant)
    observed, models = tmp_path / "observed.json", tmp_path / "models"
    with tempfile.TemporaryDirectory() as work:
        src = build_workspace(variant, Path(work) / "ws")
        files = [resolve_launch(spec, Workspace([src.parent], DiagnosticSink())) for spec in case["launch"]]
        with running_system(src, files, expect_nodes=3, timeout=45) as (uri, graph):
            result = archlog("observe", "--master", uri, "--output", observed, "--write-models", models)
            assert result.returncode == 0, result.stderr
    seen = json.loads(observed.read_text())
    assert set(seen["nodes"]) == set(graph.nodes)
    launches = [w for spec in case["launch"] for w in ("--launch", spec)]
    same = archlog("diff", variant, *launches, "--observed", observed, "--format", "json")
    assert same.returncode == 0, same.stdout
    table = json.loads(same.stdout)
    assert all(row["over_approximation"] == row["under_approximation"] == 0 for row in table.values())
    assert table["publishers"]["recovered"] == table["publishers"]["observed"] > 0
    # a model written from the observation describes the node as the master saw it
    model = yaml.safe_load((models / "camera__camera_driver.yaml").read_text())
    assert model["instance"] == "/camera/camera_driver"
    assert {"name": "/camera/image", "type": "sensor_msgs/Image"} in model["publishers"]
    # the clean twin's configuration differs from what ran: the diff says where
    other = CORPUS / "wrong_remap" / "clean"
    changed = archlog("diff", other, *launches, "--observed", observed)
    assert changed.returncode == 1 and "only recovered subscribers" in changed.stdout


def test_observe_without_a_master_is_a_clear_error() -> None:
    result = archlog("observe", "--master", "http://127.0.0.1:9")
    assert result.returncode == 2 and "cannot read the master" in result.stderr and "Traceback" not in result.stderr


def test_shipped_models_match_the_real_debian_nodes(tmp_path: Path) -> None:
    """robot_state_publisher, joint_state_publisher (with ~source_list) and the diagnostic aggregator,
    run from Debian's packages: their models recover exactly the ports the master sees."""
    system = CORPUS.parent / "models" / "debian_nodes"
    observed = tmp_path / "observed.json"
    launch = system / "realnodes" / "launch" / "real.launch"
    with running_system(system, [launch], expect_nodes=5, timeout=45) as (uri, _graph):
        result = archlog("observe", "--master", uri, "--output", observed)
        assert result.returncode == 0, result.stderr
    diff = archlog("diff", system, "--launch", "realnodes/real.launch", "--observed", observed, "--format", "json")
    assert diff.returncode == 0, diff.stdout
    table = json.loads(diff.stdout)
    assert {kind: row["observed"] for kind, row in table.items()} == {
        "nodes": 5, "publishers": 8, "subscribers": 5, "services": 1}


def test_observe_reads_saved_ros2_node_info(tmp_path: Path) -> None:
    saved = ROOT / "corpus" / "observed" / "talker_listener.node_info.txt"
    result = archlog("observe", "--ros2-node-info", saved, "--write-models", tmp_path / "models")
    assert result.returncode == 0, result.stderr
    seen = json.loads(result.stdout)
    assert seen == {"nodes": ["/listener", "/talker"], "publishers": [["/talker", "/chatter", "std_msgs/msg/String"]],
                    "subscribers": [["/listener", "/chatter", "std_msgs/msg/String"]],
                    "services": [["/listener", "/listener/reset"]]}
    assert yaml.safe_load((tmp_path / "models" / "talker.yaml").read_text())["publishers"] == [
        {"name": "/chatter", "type": "std_msgs/msg/String"}]
    broken = tmp_path / "broken.txt"
    broken.write_text("/a\n  Publishers:\n    chatter\n")
    bad = archlog("observe", "--ros2-node-info", broken)
    assert bad.returncode == 2 and f"{broken}:3:" in bad.stderr and "Traceback" not in bad.stderr
