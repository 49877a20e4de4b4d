"""pluginlib classes a node's parameters choose (node model `plugins:` slots and `classes:`)."""

from __future__ import annotations

from pathlib import Path

from archlog.analysis import analyse


def ports(tmp_path: Path, node_xml: str) -> tuple[set[tuple[str, str]], list[str]]:
    """/move_base's (relation, name) ports and the plugin-no-model notes of a one-node launch file."""
    pkg = tmp_path / "src" / "nav"
    pkg.mkdir(parents=True)
    (pkg / "package.xml").write_text("<package format='2'><name>nav</name><version>0.1.0</version><description>d"
                                     "</description><maintainer email='a@b.c'>m</maintainer><license>MIT</license>"
                                     "</package>")
    launch = pkg / "nav.launch"
    launch.write_text(f"<launch>{node_xml}</launch>")
    analysis = analyse([tmp_path], [str(launch)], {}, [])
    found = {(relation, str(row[2])) for relation in ("publisher", "subscriber", "service_server")
             for row in analysis.store.rows(relation) if str(row[1]) == "/move_base"}
    notes = [d.message for d in analysis.diagnostics.items if d.code == "plugin-no-model"]
    return found, notes


def test_planners_named_by_parameters_live_in_their_class_namespace(tmp_path: Path) -> None:
    found, notes = ports(tmp_path, """<node pkg="move_base" type="move_base" name="move_base">
      <param name="base_local_planner" value="dwa_local_planner/DWAPlannerROS"/>
      <param name="DWAPlannerROS/odom_topic" value="wheel_odom"/></node>""")
    assert {("publisher", "/move_base/DWAPlannerROS/trajectory_cloud"), ("subscriber", "/wheel_odom"),
            ("service_server", "/move_base/DWAPlannerROS/set_parameters"),
            ("publisher", "/move_base/NavfnROS/plan"), ("service_server", "/move_base/NavfnROS/make_plan")} <= found
    assert not any("TrajectoryPlannerROS" in name for _kind, name in found)  # the default planner is replaced
    assert notes == []


def test_costmap_layers_from_the_plugins_list_and_their_observation_sources(tmp_path: Path) -> None:
    found, _notes = ports(tmp_path, """<node pkg="move_base" type="move_base" name="move_base">
      <rosparam ns="local_costmap">
        plugins: [{name: obstacles, type: "costmap_2d::VoxelLayer"}, {name: inflation, type: "costmap_2d::InflationLayer"}]
        obstacles: {observation_sources: "laser bumper", laser: {topic: /front/scan, data_type: LaserScan},
                    bumper: {data_type: PointCloud2}}
      </rosparam></node>""")
    assert {("subscriber", "/front/scan"), ("subscriber", "/bumper"),
            ("publisher", "/move_base/local_costmap/obstacles/clearing_endpoints"),
            ("publisher", "/move_base/local_costmap/inflation/parameter_updates")} <= found
    assert ("publisher", "/move_base/local_costmap/obstacles/voxel_grid") not in found  # publish_voxel_map: false
    # the global costmap has no plugins list: costmap_2d's pre-hydro layers (no static layer without static_map)
    assert ("publisher", "/move_base/global_costmap/obstacle_layer/parameter_updates") in found
    assert not any("global_costmap/static_layer" in name for _kind, name in found)


def test_a_class_without_a_model_is_reported(tmp_path: Path) -> None:
    found, notes = ports(tmp_path, """<node pkg="move_base" type="move_base" name="move_base">
      <param name="base_global_planner" value="my_planners/LanePlanner"/></node>""")
    assert notes and "my_planners/LanePlanner" in notes[0] and "base_global_planner" in notes[0]
    assert not any("NavfnROS" in name for _kind, name in found)


def test_sources_not_known_statically_make_a_port_whose_name_is_unknown(tmp_path: Path) -> None:
    found, _notes = ports(tmp_path, """<node pkg="move_base" type="move_base" name="move_base">
      <rosparam ns="local_costmap">plugins: [{name: obstacles, type: "costmap_2d::ObstacleLayer"}]</rosparam>
      <param name="local_costmap/obstacles/observation_sources" value="$(env LASER_SOURCES)"/></node>""")
    unknown = [(kind, name) for kind, name in found if name.startswith("?")]
    assert unknown == [("subscriber", "?(each word of ~local_costmap/obstacles/observation_sources "
                                      "($(env LASER_SOURCES) (environment variable LASER_SOURCES is not given)))")]
