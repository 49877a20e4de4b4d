"""Graph views: DOT with clusters and findings, focus, SVG, and the HTML page in a real browser."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from xml.etree import ElementTree

import pytest
from conftest import CORPUS, ROOT

CASE = ["graph", str(CORPUS / "topic_typo" / "buggy"), "--launch", "waypoint_nav/launch/follow_waypoints.launch"]
CHROMIUM = shutil.which("chromium")
needs = pytest.mark.skipif((CHROMIUM is None or shutil.which("dot") is None or
                            not (ROOT / "tests" / "browser" / "node_modules").is_dir()) and not os.environ.get("CI"),
                           reason="needs Debian's chromium, graphviz and tests/browser's npm packages (bash .ci/run)")


def archlog(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "archlog", *args], capture_output=True, text=True, cwd=ROOT,
                          timeout=300)


def test_dot_has_namespaces_findings_and_near_misses() -> None:
    dot = archlog(*CASE, "--format", "dot", "--parameters").stdout
    assert 'subgraph cluster_0 { label="/rover"' in dot
    assert '"t:/rover/base_waypoint" [label="/rover/base_waypoint", shape=ellipse, color="#d62728"' in dot
    assert '"t:/rover/base_waypoint" -> "t:/rover/base_waypoints" [style=dashed' in dot
    assert "src/waypoint_nav/src/pure_pursuit.cpp:45 subscriber nav_msgs/Path" in dot
    assert 'shape=note' in dot and "read by /rover/pure_pursuit" in dot  # parameters


def test_focus_keeps_the_neighbourhood() -> None:
    dot = archlog(*CASE, "--format", "dot", "--focus", "/rover/odom", "--depth", "1").stdout
    labels = {line.split('label="')[1].split('"')[0] for line in dot.splitlines()
              if "shape=" in line and "shape=note" not in line}
    assert labels == {"/rover/odom", "/rover/sim", "/rover/pure_pursuit"}
    assert archlog(*CASE, "--focus", "/nowhere").returncode == 2


def test_parameters_are_left_out_unless_asked_for() -> None:
    assert "shape=note" not in archlog(*CASE, "--format", "dot").stdout
    assert "shape=note" in archlog(*CASE, "--format", "dot", "--parameters").stdout
    param = next(line for line in archlog(*CASE, "--format", "dot", "--parameters").stdout.splitlines()
                 if "shape=note" in line).split('label="')[1].split('"')[0]
    focused = archlog(*CASE, "--format", "dot", "--focus", param, "--depth", "1").stdout
    assert f'"p:{param}" [label="{param}", shape=note' in focused  # a focused parameter is drawn


def test_focus_misspelled_gets_a_did_you_mean() -> None:
    result = archlog(*CASE, "--format", "dot", "--focus", "/rover/base_waypoit")
    assert result.returncode == 2
    assert "no node, topic, service, action or parameter named /rover/base_waypoit; did you mean " \
           "/rover/base_waypoint or /rover/base_waypoints" in result.stderr


def test_depth_one_keeps_the_near_miss_partner() -> None:
    """The subscriber's topic is one edge away; its near-miss partner two, and kept all the same."""
    dot = archlog(*CASE, "--format", "dot", "--focus", "/rover/pure_pursuit", "--depth", "1").stdout
    labels = {line.split('label="')[1].split('"')[0] for line in dot.splitlines() if "shape=" in line}
    assert labels == {"/rover/pure_pursuit", "/rover/base_waypoint", "/rover/base_waypoints", "/rover/cmd_vel",
                      "/rover/odom"}
    assert '"t:/rover/base_waypoint" -> "t:/rover/base_waypoints" [style=dashed' in dot
    assert '"n:/rover/waypoint_loader" [' not in dot  # the partner's publisher is one edge further


@needs
def test_svg_is_xml_with_one_group_per_element() -> None:
    svg = ElementTree.fromstring(archlog(*CASE, "--format", "svg").stdout)
    ids = {g.get("id") for g in svg.iter("{http://www.w3.org/2000/svg}g") if g.get("class") == "node"}
    assert {"n:/rover/pure_pursuit", "t:/rover/base_waypoint", "t:/rover/cmd_vel"} <= ids


DRIVER = ROOT / "tests" / "browser" / "check_graph.mjs"


@needs
def test_html_page_in_chromium_as_a_person_uses_it(tmp_path: Path) -> None:
    """Playwright drives Debian's Chromium: type a search, click an element, zoom, screenshot."""
    page = tmp_path / "graph.html"
    assert archlog(*CASE, "--output", str(page)).returncode == 0
    text = page.read_text()
    assert "http://" not in text.replace("http://www.w3.org", "") and "<script src" not in text  # offline
    shot = tmp_path / "graph.png"
    run = subprocess.run(["node", str(DRIVER), str(page), str(shot), "base_waypoint", "t:/rover/base_waypoint"],
                         capture_output=True, text=True, timeout=120, cwd=DRIVER.parent)
    assert run.returncode == 0, run.stderr
    seen = json.loads(run.stdout)
    assert seen["elements"] >= 7 and seen["matches"] == 2 and seen["count"] == "2 matches"
    assert seen["panel"].startswith("topic /rover/base_waypoint")
    assert "src/waypoint_nav/src/pure_pursuit.cpp:45" in seen["panel"] and "AL102" in seen["panel"]
    assert seen["zoomed"]
    assert seen["legend"].split() == ["node", "topic", "service", "action", "parameter", "error", "warning", "note",
                                      "→", "publishes,", "serves", "⇢", "client,", "near", "miss?", "…", "parameter",
                                      "read"]
    assert seen["parametersHidden"] == 0 and seen["parametersShown"] >= 1  # hidden until toggled
    [finding] = seen["findings"]
    assert finding.startswith("AL102 /rover/pure_pursuit subscribes to /rover/base_waypoint")
    assert seen["focused"] == ["n:/rover/pure_pursuit", "n:/rover/waypoint_loader", "t:/rover/base_waypoint",
                               "t:/rover/base_waypoints"]
    assert seen["dimmed"] >= 2 and seen["refocused"]
    assert seen["findingPanel"].startswith("AL102 error") and "pure_pursuit.cpp:45" in seen["findingPanel"]
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 10_000


FIXTURES = ROOT / "archlog" / "rules" / "builtin" / "tests"


def fixture_graph(case: str, extra: dict[str, list[list]] | None = None):
    """The graph of a rule fixture's facts (with `extra` rows), and its findings."""
    from archlog.queries.rule_tests import load_facts
    from archlog.queries.session import Session
    from archlog.reports import graph as views
    from archlog.rules.ruleset import load_rules

    facts = json.loads((FIXTURES / case / "facts.json").read_text())
    for relation, rows in (extra or {}).items():
        facts.setdefault(relation, []).extend(rows)
    path = Path(os.environ.get("TMPDIR", "/tmp")) / f"archlog-graph-{os.getpid()}-{case}.json"
    path.write_text(json.dumps(facts))
    try:
        store = load_facts(path)
    finally:
        path.unlink()
    return views.build(store, Session(store, load_rules([])).findings())


def test_a_starved_input_gets_a_dashed_edge_to_its_candidate_which_is_not_drawn_faulty() -> None:
    """AL601 names a near-miss candidate publisher: a dashed edge joins the two topics, the
    candidate's topic is the other side (a dashed grey outline), not coloured as the fault."""
    from archlog.reports import graph as views

    g = fixture_graph("AL601_required_input_unreachable")
    dot = views.to_dot(views.shown(g, set()))
    assert '"t:/odom_pose" -> "t:/odom_pos" [style=dashed, color="#d62728", label="near miss?"' in dot
    assert '"t:/odom_pose" [label="/odom_pose", shape=ellipse, color="#d62728", penwidth=2.5,' in dot
    assert '"t:/odom_pos" [label="/odom_pos", shape=ellipse, color="#555555", penwidth=1.5, style=dashed,' in dot
    assert g.graph.nodes["t:/odom_pos"]["severity"] is None and g.graph.nodes["t:/odom_pos"]["other"]


def test_infrastructure_is_hidden_unless_asked_for_or_named() -> None:
    """tf, dynamic_reconfigure, rosout and ROS 2 built-in ports, and topics with one side only,
    are left out by default (as rqt_graph does) and drawn when their group is asked for; a topic
    a finding names stays whatever its group."""
    from archlog.reports import graph as views

    extra = {"publisher": [["x1", "/base", "/tf", "tf2_msgs/msg/TFMessage"],
                           ["x2", "/base", "/base/parameter_updates", "dynamic_reconfigure/Config"],
                           ["x3", "/base", "/rosout", "rosgraph_msgs/Log"],
                           ["x4", "/localizer", "/parameter_events", "rcl_interfaces/msg/ParameterEvent"]],
             "service_server": [["x5", "/base", "/base/set_parameters", "dynamic_reconfigure/Reconfigure"]],
             "infrastructure_port": [["x4", "parameter_events"]]}
    g = fixture_graph("AL601_required_input_unreachable", extra)
    groups = {ident: data["group"] for ident, data in g.graph.nodes(data=True) if data["group"]}
    assert {ident: group for ident, group in groups.items() if group != "leaf topics"} == {
        "t:/tf": "tf", "t:/base/parameter_updates": "dynamic_reconfigure", "s:/base/set_parameters": "dynamic_reconfigure",
        "t:/rosout": "rosout", "t:/parameter_events": "built-in"}
    assert groups["t:/odom"] == "leaf topics" and "t:/trajectory" not in groups  # /trajectory has both sides
    default = set(views.shown(g, set()).graph)
    assert not default & {"t:/tf", "t:/base/parameter_updates", "s:/base/set_parameters", "t:/rosout",
                          "t:/parameter_events", "t:/odom"}
    assert {"t:/odom_pose", "t:/odom_pos", "n:/base", "t:/trajectory"} <= default  # named by AL601, or both sides
    assert "t:/tf" in views.shown(g, {"tf"}).graph and "t:/rosout" not in views.shown(g, {"tf"}).graph
    everything = views.shown(g, set(views.GROUPS)).graph
    assert set(everything) == set(g.graph)


def test_show_draws_the_hidden_groups_of_a_ros2_system() -> None:
    """Every rclpy node's built-in ports (parameter services, /parameter_events), /rosout and a
    topic nothing subscribes are left out of the default drawing, and --show draws each group."""
    case = ["graph", str(ROOT / "corpus" / "ros2" / "param_name_typo_py" / "clean"), "--launch",
            "follow_me/launch/follow.launch.py", "--format", "dot"]
    drawn = lambda *show: {line.split('"')[1] for line in archlog(*case, *show).stdout.splitlines()  # noqa: E731
                           if "shape=" in line}
    default = drawn()
    assert {"n:/follower", "n:/scan_filter", "t:/scan_filtered"} <= default
    assert not {"t:/rosout", "t:/parameter_events", "s:/follower/get_parameters", "t:/cmd_vel"} & default
    assert drawn("--show", "rosout") == default | {"t:/rosout"}
    assert drawn("--show", "leaf topics") == default | {"t:/cmd_vel"}
    assert {"t:/parameter_events", "s:/follower/get_parameters", "s:/scan_filter/set_parameters"} <= \
        drawn("--show", "built-in") - default
    assert drawn("--show", "all") == drawn("--show", "rosout", "--show", "leaf topics", "--show", "built-in")
