"""Ports from command lines and configuration files: rosbag record topic lists, rviz displays."""

from __future__ import annotations

from pathlib import Path

from archlog.analysis import analyse
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules

RVIZ = """Panels: []
Visualization Manager:
  Displays:
    - Class: rviz/LaserScan
      Enabled: true
      Name: LaserScan
      Topic: /scan
    - Class: rviz/Group
      Enabled: true
      Displays:
        - Class: rviz/Path
          Enabled: true
          Topic: /planner/plan
        - Class: rviz/Image
          Enabled: false
          Image Topic: /camera/image_raw
    - Class: rviz/MarkerArray
      Enabled: true
      Marker Topic: /markers
  Tools:
    - Class: rviz/SetGoal
      Topic: /goal
    - Class: rviz/SetInitialPose
      Topic: /initialpose
"""


def test_rosbag_and_rviz_ports(tmp_path: Path) -> None:
    (tmp_path / "view.rviz").write_text(RVIZ)
    launch = tmp_path / "tools.launch"
    launch.write_text("""<launch>
  <node pkg="rosbag" type="record" name="bag" args="-O /tmp/run.bag --split --size 1024 /scan /odom"/>
  <node pkg="rviz" type="rviz" name="rviz" args="-d $(dirname)/view.rviz"/>
</launch>""")
    result = analyse([tmp_path], [str(launch)], {}, [])
    subs = sorted((n, t, ty if isinstance(ty, str) else "?") for _p, n, t, ty in result.store.rows("subscriber"))
    assert subs == [("/bag", "/odom", "?"), ("/bag", "/scan", "?"),
                    ("/rviz", "/markers", "visualization_msgs/MarkerArray"),
                    ("/rviz", "/planner/plan", "nav_msgs/Path"), ("/rviz", "/scan", "sensor_msgs/LaserScan")]
    pubs = sorted((t, ty) for _p, n, t, ty in result.store.rows("publisher") if n == "/rviz")
    assert pubs == [("/goal", "geometry_msgs/PoseStamped"), ("/initialpose", "geometry_msgs/PoseWithCovarianceStamped")]
    scan = next(p for p, n, t, _ty in result.store.rows("subscriber") if n == "/rviz" and t == "/scan")
    assert result.store.location(scan)[1] == 4  # the display's line in view.rviz
    assert [d.code for d in result.diagnostics.items] == []
    Engine(load_rules([])).run(result.store)  # unknown types never make a type mismatch
