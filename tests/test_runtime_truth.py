"""Runtime ground truth: corpus systems (rospy, and roscpp built with g++ against Debian's ROS)
launched with Debian's roslaunch on a loopback master; the live graph read from the master must
equal the recovered architecture: nodes, publishers and subscribers with types, services."""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest

from archlog.analysis import resolve_launch
from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace import Workspace
from conftest import corpus_cases, load_case, requires_ros, run_case
from support.build_cpp import build_workspace
from support.live_graph import launch_graph

pytestmark = requires_ros()

RUNTIME = [v for v in corpus_cases() if load_case(v).get("runtime")]


def recovered(store) -> dict[str, set]:
    types: dict[str, set] = {}
    for rel in ("publisher", "subscriber"):
        for _p, _n, topic, type_ in store.rows(rel):
            types.setdefault(topic, set()).add(type_)
    return {
        "nodes": {row[0] for row in store.rows("node")},
        "publishers": {(n, t, ty) for _p, n, t, ty in store.rows("publisher")},
        "subscribers": {(n, t) for _p, n, t, _ty in store.rows("subscriber")},
        # the master keeps one type per topic (the first registration): compare where it is unambiguous
        "topic_types": {t: next(iter(ty)) for t, ty in types.items() if len(ty) == 1},
        "services": {(n, s) for _p, n, s, _ty in store.rows("service_server")},
    }


def test_enough_runtime_systems() -> None:
    assert len({v.parent.name for v in RUNTIME}) >= 6
    assert any((v / "src").rglob("*.cpp") for v in RUNTIME)


@pytest.mark.parametrize("variant", RUNTIME, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_live_graph_equals_recovered_architecture(variant: Path) -> None:
    analysis, _findings = run_case(variant)
    case = load_case(variant)
    want = recovered(analysis.store)
    with tempfile.TemporaryDirectory() as tmp:
        src = build_workspace(variant, Path(tmp) / "ws")
        files = [resolve_launch(spec, Workspace([src.parent], DiagnosticSink())) for spec in case["launch"]]
        live = launch_graph(src, files, case.get("args", {}), expect_nodes=len(want["nodes"]), timeout=45)
    assert live.nodes == want["nodes"]
    assert live.publishers == want["publishers"]
    assert {(n, t) for n, t, _ty in live.subscribers} == want["subscribers"]
    assert {(t, ty) for _n, t, ty in live.subscribers if t in want["topic_types"]} == \
        {(t, want["topic_types"][t]) for _n, t in want["subscribers"] if t in want["topic_types"]}
    assert live.services == want["services"]
