"""Issue 21: the facts behind rules that stay sharp when part of the system is unknown, read on
the corpus systems built for it (roscpp handle namespaces, opaque nodes, topic parameters)."""

from __future__ import annotations

from pathlib import Path

from conftest import CORPUS, finding_keys, run_case

from archlog.analysis import Analysis, analyse


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


def test_an_input_required_alone_names_no_live_alternative() -> None:
    """goal_marker needs clicked_point alone; the goal needs clicked_point or cloud_clusters, and
    cloud_clusters is published: the finding names neither the goal nor that alternative."""
    _analysis, [finding] = run_case(CORPUS / "click_or_cluster" / "buggy")
    assert finding.message == "/goal_planner publishes /goal_marker only after it receives /clicked_point, " \
        "which nothing publishes"


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



def test_a_partly_known_name_keeps_its_known_end() -> None:
    """`'/' + socket.gethostname() + '/scan'` with a message class chosen at run time: the name is known
    to end with /scan, so it cannot feed /robot1/cmd_vel (AL601 reports it; before, it muted everything)."""
    analysis, findings = run_case(CORPUS / "partly_known_name" / "buggy")
    assert isinstance(analysis, Analysis)
    [(unknown, prefix, suffix)] = rows(analysis, "unknown_pattern")
    assert (str(unknown), prefix, suffix) == ("?('/' + socket.gethostname() + '/scan')", "", "/scan")
    assert finding_keys(findings) == [("AL601", "src/fleet_base/scripts/base_driver.py", 11, "/robot1/cmd_vel")]
    assert [d.message for d in analysis.diagnostics.items if d.code == "port-name-unknown"] == [
        "the name of this publisher is unknown: '/' + socket.gethostname() + '/scan'; it may connect to any name "
        "that ends with /scan"]


RELAY_LAUNCH = """<launch>
  <group ns="r1">
    <node pkg="relay" type="relay.py" name="relay">{remap}</node>
  </group>
</launch>
"""
RELAY = """import socket
import rospy
from sensor_msgs.msg import LaserScan
rospy.init_node('relay')
rospy.Publisher('robot_' + socket.gethostname() + '/scan/', LaserScan, queue_size=1)
rospy.Subscriber('~' + socket.gethostname(), LaserScan, print)
"""


def _relay(root: Path, remap: str, source: str = RELAY) -> dict[str, object]:
    """The name of each port of a relay in namespace /r1 whose names are partly known, and each pattern."""
    corpus = CORPUS / "partly_known_name" / "buggy" / "src" / "fleet_base"
    package = root / "src" / "relay"
    (package / "launch").mkdir(parents=True)
    (package / "scripts").mkdir()
    (package / "package.xml").write_text((corpus / "package.xml").read_text().replace("fleet_base", "relay"))
    (package / "CMakeLists.txt").write_text("cmake_minimum_required(VERSION 3.0.2)\nproject(relay)\n"
                                            "catkin_install_python(PROGRAMS scripts/relay.py DESTINATION bin)\n")
    (package / "scripts" / "relay.py").write_text(source)
    (package / "launch" / "relay.launch").write_text(RELAY_LAUNCH.format(remap=remap))
    analysis = analyse([root], ["relay/launch/relay.launch"], {}, [])
    ports = {kind: name for kind in ("publisher", "subscriber") for _p, _n, name, _t in rows(analysis, kind)}
    patterns = {name: (prefix, suffix) for name, prefix, suffix in rows(analysis, "unknown_pattern")}
    return {kind: patterns.get(name) for kind, name in ports.items()} | \
        {"publisher before remaps": patterns.get(next(n for _p, n in sorted(rows(analysis, "port_source_name"))))}


def test_known_parts_resolve_as_the_name_would(tmp_path: Path) -> None:
    """A relative prefix lies in the node's namespace, `~` in its private one; slashes are cleaned."""
    assert _relay(tmp_path, "") == {"publisher": ("/r1/robot_", "/scan"), "subscriber": ("/r1/relay", ""),
                                    "publisher before remaps": ("/r1/robot_", "/scan")}


def test_a_remap_that_may_match_makes_the_name_anything(tmp_path: Path) -> None:
    """Remaps apply to the resolved name: when a remap's source fits the known parts, the name after
    remapping may be the remap's target too, so only the name before remapping keeps them."""
    assert _relay(tmp_path, '<remap from="robot_7/scan" to="/front_scan"/>') == {
        "publisher": None, "subscriber": ("/r1/relay", ""), "publisher before remaps": ("/r1/robot_", "/scan")}


def test_names_from_get_namespace_resolve_as_roscpp_does(tmp_path: Path) -> None:
    """corpus/cpp_ros1/roscpp_namespace_edits.cpp in namespace /r1, its "arm" handle remapped: getNamespace()
    is the handle's resolved, remapped namespace; a name made relative by erasing its slash resolves again. A
    handle in a namespace known only at run time keeps what is known of it (the private namespace it lies in)."""
    package = tmp_path / "src" / "odometry"
    (package / "src").mkdir(parents=True)
    (package / "launch").mkdir()
    (package / "package.xml").write_text(
        (CORPUS / "namespace_prefix" / "clean" / "src" / "rover_base" / "package.xml").read_text()
        .replace("rover_base", "odometry"))
    (package / "CMakeLists.txt").write_text("cmake_minimum_required(VERSION 3.0.2)\nproject(odometry)\n"
                                            "add_executable(odometer src/odometer.cpp)\n")
    (package / "src" / "odometer.cpp").write_text(
        (CORPUS.parent / "cpp_ros1" / "roscpp_namespace_edits.cpp").read_text())
    (package / "launch" / "odometer.launch").write_text(
        '<launch><group ns="r1"><node pkg="odometry" type="odometer" name="odometer">'
        '<remap from="arm" to="manipulator"/></node></group></launch>')
    analysis = analyse([tmp_path], ["odometry/launch/odometer.launch"], {}, [])
    assert sorted(str(name) for kind in ("publisher", "subscriber") for _p, _n, name, _t in rows(analysis, kind)) == [
        "/r1/heartbeat", "/r1/r1/manipulator/command", "/r1/r1/odom", "/r1/r1/odometer/scan", "/r1/r1/relay",
        "/r1/status", "?('~/' + argv [ 1 ]/state)", "?(chosen (string edits not understood) + '/debug')"]
    assert {(str(u), p, s) for u, p, s in rows(analysis, "unknown_pattern")} == {
        ("?(chosen (string edits not understood) + '/debug')", "", "/debug"),
        ("?('~/' + argv [ 1 ]/state)", "/r1/odometer", "/state")}



def test_a_name_that_is_one_of_several_partly_known_keeps_only_what_all_share(tmp_path: Path) -> None:
    """`host + ('/scan_best' if fast else '/front_scan')` ends with /scan_best or /front_scan: the
    pattern keeps what both end with, never one option's end alone (that claims /front_scan cannot be it)."""
    either = RELAY.replace("'/scan/'", "('/scan_best' if rospy.get_param('~fast', False) else '/front_scan')")
    assert _relay(tmp_path, "", either)["publisher"] == ("/r1/robot_", "")
