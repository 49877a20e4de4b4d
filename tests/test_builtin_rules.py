"""Built-in rules on small fact stores: each rule fires where it should and stays quiet otherwise."""

from __future__ import annotations

from archlog.facts.near_misses import add_near_names
from archlog.facts.store import FactStore
from archlog.queries.rule_tests import load_facts
from archlog.rules.engine import Engine
from archlog.rules.ruleset import BUILTIN, load_rules
from archlog.values import Unknown

ENGINE = Engine(load_rules([]))


def system(*ports: tuple[str, str, str, object, str]) -> FactStore:
    """Ports as (relation, port id, node, name, type); near misses are added as `check` adds them."""
    store = FactStore()
    for relation, pid, node, name, type_ in ports:
        store.add(relation, pid, node, name, type_)
        store.locate(pid, f"{node.strip('/')}.py", int(pid[1:]))
    add_near_names(store, 0.5)
    return store


def found(store: FactStore) -> list[tuple[str, str, int]]:
    return [(f.rule.id, f.location.file, f.location.line) for f in ENGINE.run(store)[1]]


def test_orphan_subscriber_with_connected_publisher_of_its_type() -> None:
    store = system(("publisher", "p1", "/laser", "/front/scan", "sensor_msgs/LaserScan"),
                   ("subscriber", "p2", "/rviz", "/front/scan", "sensor_msgs/LaserScan"),
                   ("subscriber", "p3", "/amcl", "/base_laser", "sensor_msgs/LaserScan"))
    assert found(store) == [("AL104", "amcl.py", 3)]


def test_no_dangling_guess_when_a_publisher_name_is_unknown() -> None:
    store = system(("publisher", "p1", "/laser", "/front/scan", "sensor_msgs/LaserScan"),
                   ("subscriber", "p2", "/rviz", "/front/scan", "sensor_msgs/LaserScan"),
                   ("publisher", "p4", "/relay", Unknown("topic_from_cli()", "relay.py", 4), "sensor_msgs/LaserScan"),
                   ("subscriber", "p3", "/amcl", "/base_laser", "sensor_msgs/LaserScan"))
    assert found(store) == []


def test_service_provided_twice_and_not_provided() -> None:
    store = system(("service_server", "p1", "/map_a", "/static_map", "nav_msgs/GetMap"),
                   ("service_server", "p2", "/map_b", "/static_map", "nav_msgs/GetMap"),
                   ("service_client", "p3", "/planner", "/static_map", "nav_msgs/GetMap"),
                   ("service_client", "p4", "/planner", "/make_plan", "nav_msgs/GetPlan"))
    assert found(store) == [("AL202", "map_b.py", 2), ("AL201", "planner.py", 4)]


def test_connected_system_is_quiet_and_mismatch_needs_known_types() -> None:
    store = system(("publisher", "p1", "/a", "/chatter", "std_msgs/String"),
                   ("subscriber", "p2", "/b", "/chatter", Unknown("T", "b.py", 2)),
                   ("subscriber", "p3", "/c", "/chatter", "std_msgs/String"))
    assert found(store) == []
    store.add("subscriber", "p9", "/d", "/chatter", "std_msgs/Int32")
    store.locate("p9", "d.py", 9)
    assert found(store) == [("AL101", "d.py", 9)]


def test_near_miss_on_a_dangling_publisher_whose_counterpart_is_connected() -> None:
    store = system(("publisher", "p1", "/teleop", "/cmd_vel", "geometry_msgs/Twist"),
                   ("subscriber", "p2", "/base", "/cmd_vel", "geometry_msgs/Twist"),
                   ("publisher", "p3", "/planner", "/cmd_vell", "geometry_msgs/Twist"))
    [finding] = ENGINE.run(store)[1]
    assert (finding.rule.id, finding.location.line, finding.values["role"]) == ("AL102", 3, "publishes")
    assert [r.line for r in finding.related] == [2]


def test_unreachable_required_input_lists_what_it_silences() -> None:
    """AL601 is reported once at the root, listing the outputs held back, the near-miss publishers
    and the nodes silenced downstream (the list columns of its header)."""
    from pathlib import Path

    from archlog.queries.rule_tests import load_facts

    case = Path(__file__).resolve().parent.parent / "archlog/rules/builtin/tests/AL601_required_input_unreachable"
    [finding] = [f for f in ENGINE.run(load_facts(case / "facts.json"))[1] if f.rule.id == "AL601"]
    assert finding.values["outputs"] == "/trajectory"
    assert finding.values["near"] == "; candidates: /odom_pos"
    assert finding.values["silenced"] == "; nodes silenced downstream: /follower"
    assert finding.values["unseen"] == ""  # an empty list with a phrase leaves no text
    assert (finding.location.file, finding.location.line) == ("lattice.cpp", 20)
    # the other side is the candidate's publisher (/localizer's /odom_pos), not the node's own publish call
    assert [(r.file, r.line) for r in finding.related] == [("localizer.py", 5)]


def test_opaque_nodes_block_only_where_they_might_be_the_counterpart() -> None:
    """Issue 21: an opaque node remapped onto a name keeps a rule from concluding there; elsewhere
    the finding is reported and names the opaque nodes, or counts them when there are many."""
    def store(opaque: int) -> FactStore:
        facts = system(("publisher", "p1", "/laser", "/front/scan", "sensor_msgs/LaserScan"),
                       ("subscriber", "p2", "/rviz", "/front/scan", "sensor_msgs/LaserScan"),
                       ("subscriber", "p3", "/amcl", "/base_laser", "sensor_msgs/LaserScan"),
                       ("subscriber", "p4", "/amcl", "/rear_laser", "sensor_msgs/LaserScan"),
                       ("subscriber", "p5", "/amcl", "/vendor1/scan", "sensor_msgs/LaserScan"))
        for node in ("/laser", "/rviz", "/amcl"):
            facts.add("node", node, "pkg", node[1:], "e0")
            facts.add("node_source", node, "cpp")
        for i in range(opaque):
            facts.add("node", f"/vendor{i}", "vendor", "driver", "e0")
        facts.add("remap", "e9", "/vendor0", "/scan", "/rear_laser")
        facts.add("private_name", "/vendor1/scan", "/vendor1")
        return facts

    [few] = ENGINE.run(store(2))[1]
    # /rear_laser: /vendor0 is remapped onto it; /vendor1/scan: in /vendor1's private namespace
    assert (few.rule.id, few.location.line) == ("AL104", 3)
    assert few.message.endswith("(unless /vendor0, /vendor1, which archlog cannot see into, publishes it)")
    [many] = ENGINE.run(store(6))[1]
    assert many.message.endswith("(unless one of the 6 nodes archlog cannot see into publishes it)")




def test_near_miss_names_the_nearest_namespace_and_relates_the_equally_near_others() -> None:
    store = system(("subscriber", "p1", "/arm/ctl", "/arm/joint_cmd", "trajectory_msgs/JointTrajectory"),
                   ("publisher", "p2", "/alm/planner", "/alm/joint_cmd", "trajectory_msgs/JointTrajectory"),
                   ("publisher", "p3", "/arm/planner", "/arm/joint_cmds", "trajectory_msgs/JointTrajectory"),
                   ("publisher", "p4", "/arn/planner", "/arn/joint_cmd", "trajectory_msgs/JointTrajectory"))
    [finding] = [f for f in ENGINE.run(store)[1] if f.rule.id == "AL102"]
    assert finding.values["other_topic"] == "/arm/joint_cmds" and finding.values["others"] == 2
    assert sorted(r.line for r in finding.related) == [2, 3, 4]


def test_near_miss_in_a_fleet_is_the_same_robots_counterpart() -> None:
    ports = [port for k in range(1, 4) for port in (
        ("publisher", f"p{k}1", f"/robot_{k}/lidar", f"/robot_{k}/front/scan", "sensor_msgs/LaserScan"),
        ("subscriber", f"p{k}2", f"/robot_{k}/filter", f"/robot_{k}/front/{'scna' if k == 2 else 'scan'}",
         "sensor_msgs/LaserScan"))]
    findings = [f for f in ENGINE.run(system(*ports))[1] if f.rule.id == "AL102"]
    assert [(f.values["topic"], f.values["other_topic"], f.values["others"]) for f in findings] == [
        ("/robot_2/front/scna", "/robot_2/front/scan", 0)]


def test_an_optional_input_is_no_dangling_end() -> None:
    """A subscriber a model marks optional (a reset users may send) is not paired with an unheard
    publisher of its type (AL103), nor reported as unfed while another node publishes its type (AL104)."""
    pose = "geometry_msgs/PoseWithCovarianceStamped"
    ports = (("publisher", "p1", "/amcl", "/amcl_pose", pose), ("subscriber", "p2", "/ekf", "/set_pose", pose))
    assert found(system(*ports)) == [("AL103", "amcl.py", 1)]
    store = system(*ports)
    store.add("optional_port", "p2")
    assert found(store) == []
    heard = system(*ports, ("subscriber", "p3", "/rviz", "/amcl_pose", pose))
    assert found(heard) == [("AL104", "ekf.py", 2)]
    heard.add("optional_port", "p2")
    assert found(heard) == []


def test_an_output_needing_only_an_optional_input_is_no_starved_output() -> None:
    """AL601's own fixture: /lattice's trajectory needs /odom_pose, which nothing publishes; marked
    optional, the input is one the node works without, and nothing is reported."""
    store = load_facts(BUILTIN / "tests" / "AL601_required_input_unreachable" / "facts.json")
    assert [rule for rule, _f, _l in found(store)] == ["AL601"]
    store.add("optional_port", "p1")
    assert found(store) == []
