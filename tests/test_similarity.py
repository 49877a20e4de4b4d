"""Near-miss names: the pinned examples and the prefix filter's completeness."""

from __future__ import annotations

import itertools

from hypothesis import given, settings
from hypothesis import strategies as st

from archlog.facts.similarity import distance, near_names, near_pairs


def test_pinned_examples() -> None:
    assert distance("/base_waypoint", "/base_waypoints") < 0.5
    assert distance("/vector_map_info/point", "/vector_map_info/point_class") < 0.5
    assert distance("/vector_map_info/point", "/vector_map_info/line") >= 0.5
    assert distance("/odom", "/odometry") >= 0.5
    assert distance("/cmd_vel", "/cmd_vel") == 0


def test_transposed_segments_are_near() -> None:
    assert distance("/map_vector/info", "/vector_map/info") < 0.5


def test_near_pairs_lists_each_pair_once() -> None:
    pairs = near_pairs(["/base_waypoint", "/base_waypoints", "/vector_map_info/line", "/odom"])
    assert [(a, b) for a, b, _ in pairs] == [("/base_waypoint", "/base_waypoints")]


WORDS = ["scan", "scan2", "robot_1", "robot_2", "1", "12", "a1", "cmd", "vel", "map", "odom", "odm", "image", "raw", "base"]
name = st.lists(st.lists(st.sampled_from(WORDS), min_size=1, max_size=2).map("_".join), min_size=1, max_size=4) \
    .map(lambda segs: "/" + "/".join(segs))


@settings(max_examples=60, deadline=None)
@given(st.lists(name, min_size=2, max_size=25, unique=True), st.sampled_from([0.3, 0.5, 0.8]))
def test_prefix_filter_finds_every_pair_brute_force_finds(names: list[str], threshold: float) -> None:
    brute = sorted((a, b) for a, b in itertools.combinations(sorted(names), 2) if distance(a, b) < threshold)
    assert [(a, b) for a, b, _ in near_pairs(names, threshold)] == brute


def test_names_whose_numbers_differ_are_never_near() -> None:
    assert distance("/robot_3/front_lidar/scan", "/robot_4/front_lidar/scan") == float("inf")
    assert distance("/camera1/image_raw", "/camera2/image_raw") == float("inf")
    assert distance("/robot_3/front_lidar/scna", "/robot_3/front_lidar/scan") < 0.5


def test_a_missing_namespace_is_near_whatever_its_numbers() -> None:
    assert distance("/cmd_vel", "/robot1/cmd_vel") < 0.5
    assert near_names(["/cmd_vel"], ["/robot1/cmd_vel", "/robot2/cmd_vel", "/robot1/odom"]) == [
        ("/cmd_vel", "/robot1/cmd_vel", distance("/cmd_vel", "/robot1/cmd_vel")),
        ("/cmd_vel", "/robot2/cmd_vel", distance("/cmd_vel", "/robot2/cmd_vel"))]
    fleet = [f"/robot_{k}/front_lidar/{leaf}" for k in range(30) for leaf in ("scan", "points")]
    pairs = near_pairs([*fleet, "/robot_7/front_lidar/scna"])
    assert [(a, b) for a, b, _ in pairs] == [("/robot_7/front_lidar/scan", "/robot_7/front_lidar/scna")]


@settings(max_examples=60, deadline=None)
@given(st.lists(name, min_size=2, max_size=25, unique=True), st.data(), st.sampled_from([0.3, 0.5, 0.8, 1.6]))
def test_near_names_of_queries_are_the_pairs_brute_force_finds(names: list[str], data: st.DataObject,
                                                               threshold: float) -> None:
    queries = data.draw(st.lists(st.sampled_from(names), unique=True))
    brute = sorted((a, b) for a, b in itertools.combinations(sorted(names), 2)
                   if (a in queries or b in queries) and distance(a, b) < threshold)
    assert [(a, b) for a, b, _ in near_names(queries, names, threshold)] == brute


@settings(max_examples=60, deadline=None)
@given(st.lists(name, min_size=1, max_size=25, unique=True), st.lists(name, min_size=1, max_size=25, unique=True),
       st.sampled_from([0.3, 0.5, 0.8]))
def test_near_names_pairs_a_query_only_with_a_name_of_the_other_set(queries: list[str], names: list[str],
                                                                     threshold: float) -> None:
    brute = sorted({tuple(sorted((a, b))) for a in queries for b in names if a != b and distance(a, b) < threshold})
    assert [(a, b) for a, b, _ in near_names(queries, names, threshold)] == brute
