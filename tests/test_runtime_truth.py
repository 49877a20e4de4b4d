"""Runtime ground truth: corpus systems (rospy, and roscpp built with g++ against Debian's ROS)
launched with Debian's roslaunch on a loopback master; the live graph read from the master must
equal the recovered architecture: nodes, publishers and subscribers with types, services."""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest
from conftest import corpus_cases, load_case, requires_ros, run_case
from support.build_cpp import build_workspace
from support.live_graph import launch_graph

from archlog.analysis import resolve_launch
from archlog.diagnostics import DiagnosticSink
from archlog.extract.workspace.index import Workspace
from archlog.observe import compare, from_facts

pytestmark = requires_ros()

RUNTIME = [v for v in corpus_cases() if load_case(v).get("runtime")]


def test_enough_runtime_systems() -> None:
    assert len({v.parent.name for v in RUNTIME}) >= 6
    assert any((v / "src").rglob("*.cpp") for v in RUNTIME)


@pytest.mark.parametrize("variant", RUNTIME, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_live_graph_equals_recovered_architecture(variant: Path) -> None:
    analysis, _findings = run_case(variant)
    case = load_case(variant)
    want = from_facts(analysis.store)
    with tempfile.TemporaryDirectory() as tmp:
        src = build_workspace(variant, Path(tmp) / "ws")
        files = [resolve_launch(spec, Workspace([src.parent], DiagnosticSink())) for spec in case["launch"]]
        live = launch_graph(src, files, case.get("args", {}), expect_nodes=len(want.nodes), timeout=45)
    differences = {kind: (row["only_recovered"], row["only_observed"]) for kind, row in compare(want, live).items()}
    assert differences == {kind: ([], []) for kind in differences}
    # the master keeps one type per topic; where the recovery agrees on one, it must be that
    types: dict[str, set[str]] = {}
    for _n, topic, type_ in want.publishers | want.subscribers:
        types.setdefault(topic, set()).add(type_)
    assert {(t, ty) for _n, t, ty in live.subscribers if len(types.get(t, ())) == 1} == \
        {(t, next(iter(types[t]))) for _n, t, _ty in want.subscribers if len(types[t]) == 1}
