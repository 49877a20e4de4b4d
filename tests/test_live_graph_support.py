"""End-to-end check of tests/support/rosgraph.py against a real ROS 1 launch."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest
from conftest import requires_ros
from support.live_graph import LiveGraph, _pids_with_env, launch_graph

pytestmark = requires_ros()

PACKAGE_XML = """\
<?xml version="1.0"?>
<package format="2">
  <name>demo_graph</name>
  <version>0.0.1</version>
  <description>Tiny graph for archlog tests</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>catkin</buildtool_depend>
  <exec_depend>rospy</exec_depend>
  <exec_depend>std_msgs</exec_depend>
  <exec_depend>nav_msgs</exec_depend>
</package>
"""

CMAKELISTS = """\
cmake_minimum_required(VERSION 3.0.2)
project(demo_graph)
find_package(catkin REQUIRED COMPONENTS rospy std_msgs nav_msgs)
catkin_package()
catkin_install_python(PROGRAMS scripts/talker.py scripts/listener.py
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
"""

TALKER = """\
#!/usr/bin/env python3
import rospy
from nav_msgs.srv import GetMap, GetMapResponse
from std_msgs.msg import String

rospy.init_node("talker")
pub = rospy.Publisher("chatter", String, queue_size=10)
rospy.Service("static_map", GetMap, lambda req: GetMapResponse())
rate = rospy.Rate(5)
while not rospy.is_shutdown():
    pub.publish(String(data="hello"))
    rate.sleep()
"""

LISTENER = """\
#!/usr/bin/env python3
import rospy
from std_msgs.msg import String

rospy.init_node("listener")
rospy.Subscriber("chatter", String, lambda msg: rospy.loginfo(msg.data))
rospy.spin()
"""

LAUNCH = """\
<launch>
  <group ns="robot">
    <node pkg="demo_graph" type="talker.py" name="talker"/>
    <node pkg="demo_graph" type="listener.py" name="listener">
      <remap from="chatter" to="talk"/>
    </node>
  </group>
</launch>
"""


def _write_package(src: Path) -> Path:
    pkg = src / "demo_graph"
    (pkg / "scripts").mkdir(parents=True)
    (pkg / "launch").mkdir()
    (pkg / "package.xml").write_text(PACKAGE_XML)
    (pkg / "CMakeLists.txt").write_text(CMAKELISTS)
    for name, body in (("talker.py", TALKER), ("listener.py", LISTENER)):
        script = pkg / "scripts" / name
        script.write_text(body)
        script.chmod(0o755)
    launch = pkg / "launch" / "demo.launch"
    launch.write_text(LAUNCH)
    return launch


def test_launch_graph_reads_live_graph_and_cleans_up(tmp_path: Path) -> None:
    src = tmp_path / "src"
    launch = _write_package(src)

    graph = launch_graph(src, [launch], expect_nodes=2)

    assert graph == LiveGraph(
        nodes=frozenset({"/robot/talker", "/robot/listener"}),
        publishers=frozenset({("/robot/talker", "/robot/chatter", "std_msgs/String")}),
        # The remap leaves the listener on a topic nobody publishes; its type
        # comes from the subscriber's own registration.
        subscribers=frozenset({("/robot/listener", "/robot/talk", "std_msgs/String")}),
        services=frozenset({("/robot/talker", "/robot/static_map")}),
    )
    # Every process launch_graph starts (roscore, master, rosout, roslaunch,
    # nodes) inherits ROS_PACKAGE_PATH=src; none may survive the call.
    assert _pids_with_env(f"ROS_PACKAGE_PATH={src}".encode()) == []


def test_launch_graph_reports_roslaunch_failure(tmp_path: Path) -> None:
    src = tmp_path / "src"
    src.mkdir()
    bad = tmp_path / "bad.launch"
    bad.write_text(textwrap.dedent("""\
        <launch>
          <node pkg="no_such_package" type="x.py" name="x"/>
        </launch>
    """))

    with pytest.raises(RuntimeError, match="roslaunch exited early"):
        launch_graph(src, [bad], timeout=20.0)
    assert _pids_with_env(f"ROS_PACKAGE_PATH={src}".encode()) == []
