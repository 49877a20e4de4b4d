"""Runtime ground truth: rospy corpus systems launched with Debian's roslaunch on a loopback
master; the live graph read from the master must equal the recovered architecture."""

from __future__ import annotations

from pathlib import Path

import pytest

from archlog.analysis import resolve_launch
from conftest import corpus_cases, load_case, requires_ros, run_case
from support.live_graph import launch_graph

pytestmark = requires_ros()

RUNTIME = [v for v in corpus_cases() if load_case(v).get("runtime")]


def recovered(store) -> dict[str, set]:
    types = {}
    for _p, _n, topic, type_ in store.rows("publisher"):
        types.setdefault(topic, type_)
    for _p, _n, topic, type_ in store.rows("subscriber"):
        types.setdefault(topic, type_)
    return {
        "nodes": {row[0] for row in store.rows("node")},
        "publishers": {(n, t, ty) for _p, n, t, ty in store.rows("publisher")},
        # the master knows one type per topic (the first registration): compare with that
        "subscribers": {(n, t, types[t]) for _p, n, t, _ty in store.rows("subscriber")},
        "services": {(n, s) for _p, n, s, _ty in store.rows("service_server")},
    }


def test_enough_runtime_systems() -> None:
    assert len({v.parent.name for v in RUNTIME}) >= 4


@pytest.mark.parametrize("variant", RUNTIME, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_live_graph_equals_recovered_architecture(variant: Path) -> None:
    analysis, _findings = run_case(variant)
    case = load_case(variant)
    files = [resolve_launch(spec, analysis.workspace) for spec in case["launch"]]
    want = recovered(analysis.store)
    live = launch_graph(variant / "src", files, case.get("args", {}), expect_nodes=len(want["nodes"]), timeout=40)
    assert live.nodes == want["nodes"]
    assert live.publishers == want["publishers"]
    assert live.subscribers == want["subscribers"]
    assert live.services == want["services"]
