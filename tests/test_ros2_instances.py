"""ROS 2 node instances get the name and namespace their source gives unless the launch file sets
them, and their parameters (direct ones, and parameter-file entries whose node key matches)."""

from __future__ import annotations

from pathlib import Path

from archlog.analysis import analyse
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import Element, LaunchConfig, LaunchNode
from archlog.extract.summary import NodeSummary
from archlog.system.instances import complete_instances
from archlog.values import Unknown

ELEM = Element("e1", "bringup.launch.py", 7)


def node(name: str, namespace: str, exe: str = "talker", **kw) -> LaunchNode:
    return LaunchNode(ELEM, "demo", exe, name, namespace, **kw)


def test_launch_names_win_and_the_source_fills_in_the_rest() -> None:
    summaries = {("demo", "talker"): NodeSummary("demo", "talker", "python", default_name="talker", namespace="robot"),
                 ("demo", "listener"): NodeSummary("demo", "listener", "cpp", default_name=Unknown("name", "l.cpp", 3))}
    config = LaunchConfig(nodes=[node("", ""), node("", "/ns"), node("/chatty", ""), node("/a/chatty", "/a"),
                                 node("", "", exe="listener")])
    sink = DiagnosticSink()
    complete_instances(config, summaries, sink)
    assert [(n.name, n.namespace) for n in config.nodes] == [
        ("/robot/talker", "/robot"),      # both from the source
        ("/ns/talker", "/ns"),            # a pushed namespace replaces the source's
        ("/robot/chatty", "/robot"),      # a launch name keeps the source's namespace
        ("/a/chatty", "/a"),
        ("/listener", "/"),               # a name not known statically: the executable's
    ]
    assert [(d.line, d.code, d.severity) for d in sink.items] == [(7, "node-name", "note")]


def test_parameters_reach_the_nodes_whose_key_matches() -> None:
    entries = [("", "rate", 10, ELEM), ("/**", "use_sim_time", True, ELEM), ("/**/talker", "topic", "news", ELEM),
               ("talker", "qos.depth", 5, ELEM), ("/other", "topic", "x", ELEM)]
    config = LaunchConfig(nodes=[node("/robot/talker", "/robot", parameters=list(entries)),
                                 node("/talker", "/", parameters=list(entries))])
    complete_instances(config, {}, DiagnosticSink())
    assert {k: v[0] for k, v in config.params.items()} == {
        "/robot/talker/rate": 10, "/robot/talker/use_sim_time": True, "/robot/talker/topic": "news",
        "/talker/rate": 10, "/talker/use_sim_time": True, "/talker/topic": "news", "/talker/qos.depth": 5}


def test_the_first_matching_remap_wins_in_ros2(tmp_path: Path) -> None:
    """rcl applies the first rule that matches: a set_remap in scope comes before the node's own."""
    pkg = tmp_path / "src" / "chat"
    (pkg / "chat").mkdir(parents=True)
    (pkg / "package.xml").write_text('<package format="3"><name>chat</name><export><build_type>ament_python'
                                     '</build_type></export></package>')
    (pkg / "setup.py").write_text('from setuptools import setup\nsetup(name="chat", entry_points={"console_scripts": '
                                  '["listener = chat.listener:main"]})\n')
    (pkg / "chat" / "listener.py").write_text(
        "import rclpy\nfrom std_msgs.msg import String\n\n\ndef main():\n    rclpy.init()\n"
        "    node = rclpy.create_node('listener')\n    node.create_subscription(String, 'chatter', print, 10)\n")
    launch = tmp_path / "chat.launch.xml"
    launch.write_text('<launch>\n  <set_remap from="chatter" to="/from_scope"/>\n  <node pkg="chat" exec="listener">\n'
                      '    <remap from="chatter" to="/from_node"/>\n  </node>\n</launch>\n')
    analysis = analyse([tmp_path], [str(launch)], {}, [])
    assert [row[1:3] for row in analysis.store.rows("subscriber")] == [("/listener", "/from_scope")]
