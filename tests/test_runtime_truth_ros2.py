"""Runtime ground truth for ROS 2: every rclpy node instance of the corpus/ros2 systems (both
twins) runs for real, as a plain process on a private DDS domain, with the name, namespace, remaps
and parameters archlog recovered for it; the live graph (read by archlog.observe_ros2) must show
exactly the recovered ports of those nodes: publishers, subscribers, services, clients, action
servers and clients, with types (pkg/msg/Type), and the same non-default QoS.

Only rclpy nodes run: PyPI has no rclcpp, so C++ nodes stay static-only and are not compared. A
node whose interface package has no Python wheel (a message package of the corpus itself) cannot
be imported and is not started; `UNRUNNABLE` says which and why, and the test checks that list.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest
from conftest import CORPUS_ROS2, corpus_cases, requires_rclpy, run_case
from support.ros2_nodes import observe, private_domain, rclpy_nodes, rclpy_runs, running_nodes

from archlog.analysis import Analysis
from archlog.observe import from_facts
from archlog.observe_ros2 import Port
from archlog.values import Unknown

pytestmark = requires_rclpy()

# Compare the ports every rclpy node creates on its own (/rosout, /parameter_events, the parameter
# and type-description services) too. They are kept apart on both sides (observe_ros2's
# `infrastructure`, the facts' `infrastructure_port`): set this to True once archlog recovers them.
COMPARE_INFRASTRUCTURE = True

RELATIONS = {"publisher": ("publishers", "msg"), "subscriber": ("subscribers", "msg"),
             "service_server": ("services", "srv"), "service_client": ("clients", "srv"),
             "action_server": ("action_servers", "action"), "action_client": ("action_clients", "action")}
# systems whose rclpy nodes cannot start here: they import an interface package built from the
# corpus's own .action file, and PyPI has no wheel of it (system -> (node, package))
UNRUNNABLE = {"service_private_name": ("/dock/mission", "dock_interfaces")}

VARIANTS = [v for v in corpus_cases(CORPUS_ROS2) if v.parent.name not in UNRUNNABLE and any(
    "import rclpy" in p.read_text(errors="replace") for p in v.rglob("*") if p.is_file() and p.suffix in ("", ".py"))]


def normal_type(type_: str, kind: str) -> str:
    """pkg/Type and pkg/kind/Type are one interface: write it pkg/kind/Type."""
    parts = type_.split("/")
    return f"{parts[0]}/{kind}/{parts[1]}" if len(parts) == 2 else type_


def recovered_ports(analysis: Analysis, nodes: set[str]) -> tuple[frozenset[Port], frozenset[Port]]:
    """(own, infrastructure) ports archlog recovered for `nodes`, typed as the live graph types them."""
    infrastructure = {r[0] for r in analysis.store.rows("infrastructure_port")}
    own, infra = set(), set()
    for relation, (kind, interface) in RELATIONS.items():
        for port, node, name, type_ in analysis.store.rows(relation):
            if str(node) in nodes:
                row = (kind, str(node), str(name) if not isinstance(name, Unknown) else repr(name),
                       normal_type(str(type_), interface))
                (infra if port in infrastructure else own).add(row)
    return frozenset(own), frozenset(infra)


def test_enough_rclpy_instances_run() -> None:
    assert len(VARIANTS) >= 10
    assert sum(len(rclpy_runs(run_case(v)[0])) for v in VARIANTS) >= 14


@pytest.mark.parametrize("system", sorted(UNRUNNABLE))
def test_unrunnable_systems_lack_only_an_interface_wheel(system: str) -> None:
    node, package = UNRUNNABLE[system]
    assert importlib.util.find_spec(package) is None
    for variant in sorted(p.parent for p in (CORPUS_ROS2 / system).glob("*/case.json")):
        analysis, _findings = run_case(variant)
        assert rclpy_nodes(analysis) == {node}
        assert any(str(ty).startswith(package + "/") for _p, n, _a, ty in analysis.store.rows("action_client") if n == node)
        assert list(variant.glob(f"src/{package}/action/*.action"))


@pytest.mark.parametrize("variant", VARIANTS, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_live_rclpy_ports_equal_recovered_ports(variant: Path) -> None:
    analysis, _findings = run_case(variant)
    runs = rclpy_runs(analysis)
    names = {r.name for r in runs}
    own, infrastructure = recovered_ports(analysis, names)
    domain = private_domain()
    with running_nodes(runs, domain) as procs:
        live = observe(domain, names, timeout=30)
        failed = {r.name: p.stderr.read().decode(errors="replace")[-1500:] if p.stderr else ""
                  for r, p in zip(runs, procs) if p.poll() is not None}
    assert failed == {}
    assert names <= live.nodes
    want = own | (infrastructure if COMPARE_INFRASTRUCTURE else frozenset())
    got = frozenset(p for p in live.ports | (live.infrastructure if COMPARE_INFRASTRUCTURE else frozenset())
                    if p[1] in names)
    assert sorted(want - got) == [] and sorted(got - want) == []
    # the infrastructure ports are there, kept apart, for every node
    assert {n for _k, n, name, _t in live.infrastructure if name == "/rosout"} >= names
    # each endpoint's non-default QoS as DDS reports it is the recovered one
    assert {q for q in live.qos if q[0] in names} == from_facts(analysis.store).restricted(names).qos
