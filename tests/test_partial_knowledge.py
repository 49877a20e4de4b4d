"""Issue 21: the facts behind rules that stay sharp when part of the system is unknown, read on
the corpus systems built for it (roscpp handle namespaces, opaque nodes, topic parameters)."""

from __future__ import annotations

from conftest import CORPUS, run_case

from archlog.analysis import Analysis


def rows(analysis: object, relation: str) -> set[tuple[object, ...]]:
    assert isinstance(analysis, Analysis)
    return set(analysis.store.rows(relation))


def test_a_remapped_handle_namespace_moves_the_handles_ports() -> None:
    """roscpp resolves `ros::NodeHandle camera("camera")` with remapping, so camera:=stereo moves its
    ports; the handle's namespace before remapping is recorded for AL401."""
    analysis, findings = run_case(CORPUS / "handle_namespace_remap" / "clean")
    assert findings == []
    ports = {(str(kind), str(topic)) for kind in ("publisher", "subscriber")
             for _p, node, topic, _t in rows(analysis, kind) if node == "/auto_exposure"}
    assert ports == {("subscriber", "/stereo/left/image_raw"), ("publisher", "/stereo/exposure")}
    assert {str(ns) for _p, ns in rows(analysis, "handle_namespace")} == {"/camera"}
    assert {str(name) for _p, name in rows(analysis, "port_source_name")} >= {"/stereo/left/image_raw",
                                                                            "/stereo/exposure"}


def test_an_opaque_nodes_remaps_are_facts() -> None:
    """A node without source or model has no ports, but its remaps say which names it may use."""
    analysis, _findings = run_case(CORPUS / "opaque_vendor_node" / "clean")
    assert ("/front_lidar",) not in {(n,) for n, _o in rows(analysis, "node_source")}
    assert [(str(n), str(f), str(t)) for _e, n, f, t in rows(analysis, "remap")] == \
        [("/front_lidar", "/scan", "/front_scan")]


def test_the_uncertainty_left_is_named_and_empty_parts_are_dropped() -> None:
    _analysis, [finding] = run_case(CORPUS / "opaque_vendor_node" / "buggy")
    assert finding.rule.id == "AL601"
    assert finding.message.endswith("; candidates: /wheel_odom; unless /front_lidar, /operator_panel, which archlog "
                                    "cannot see into, publishes it")
    assert "silenced downstream" not in finding.message
    assert [(r.file, r.line) for r in finding.related] == [("src/crawler_nav/scripts/base_driver.py", 9)]


def test_topic_parameters_are_recognised() -> None:
    analysis, _findings = run_case(CORPUS / "unread_topic_param" / "buggy")
    assert {(str(p), str(n), str(t)) for p, n, t in rows(analysis, "param_topic")} == \
        {("/path_follower/path_topic", "/path_follower", "/row_plan_smoothed")}
    assert {str(p) for _port, p in rows(analysis, "port_name_param")} == {"/path_follower/plan_topic"}


def test_misplaced_remap_names_the_node_it_misses() -> None:
    """Issue 19: AL401 says which node uses the name and why the remap misses it."""
    _analysis, findings = run_case(CORPUS / "misplaced_remap" / "buggy")
    [al401] = [f for f in findings if f.rule.id == "AL401"]
    assert "(it applies to /safety/safety_stop)" in al401.message
    assert "; the name is used by /safety/obstacle_monitor, declared before the remap" in al401.message
