"""Where a C++ node creates pluginlib classes, read from its text when the AST lost the loader's type."""

from __future__ import annotations

from pathlib import Path

from archlog.analysis import analyse
from archlog.extract.cpp.clang_ast import blank_comments
from archlog.extract.cpp.plugin_loads import creates_plugin, plugin_load_lines
from archlog.reports.report import holes as holes_of
from archlog.rules.engine import Engine
from archlog.rules.ruleset import load_rules

CORPUS_CPP2 = Path(__file__).resolve().parent.parent / "corpus" / "cpp_ros2"

TEXT = """\
void Host::configure() {
  // loader_.createUniqueInstance(type) is how it is done
  navigators_.push_back(loader_.createUniqueInstance(type));
  auto layer = layer_loader_->createSharedInstance<Layer>(
    name);
  auto printed = "->createInstance(x)";
  plugin_ = createInstance(type);
}
void Other::run() { auto raw = loader.createUnmanagedInstance(type); }
"""


def test_loads_outside_comments_and_strings_within_the_node_code() -> None:
    text = blank_comments(TEXT)
    assert plugin_load_lines(text, None) == [3, 4, 9]
    assert plugin_load_lines(text, [(1, 8)]) == [3, 4]


def test_only_pluginlib_loaders_create_plugins() -> None:
    assert creates_plugin("pluginlib::ClassLoader<nav::Planner>", "createUniqueInstance")
    assert not creates_plugin("pluginlib::ClassLoader<nav::Planner>", "getName")
    assert not creates_plugin("factory::Registry", "createInstance")


HUB_MANIFEST = ("<package format='3'><name>hub</name><version>0.1.0</version><description>d</description>"
                "<maintainer email='dev@example.com'>m</maintainer><license>MIT</license>"
                "<buildtool_depend>ament_cmake</buildtool_depend><export><build_type>ament_cmake</build_type>"
                "</export></package>")
CLIENT = """#!/usr/bin/env python3
import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from fleet_msgs.action import Patrol
rclpy.init()
node = Node("mission")
client = ActionClient(node, Patrol, "patrol")
rclpy.spin(node)
"""


def test_a_plugin_load_is_a_hole_the_findings_name(tmp_path: Path) -> None:
    """A C++ node creating pluginlib classes gets a plugin_hole at the call; a client whose server
    nobody shows names it as a part not read, and the report lists it."""
    hub = tmp_path / "src" / "hub"
    (hub / "src").mkdir(parents=True)
    (hub / "scripts").mkdir()
    (hub / "package.xml").write_text(HUB_MANIFEST)
    (hub / "CMakeLists.txt").write_text("project(hub)\nfind_package(ament_cmake REQUIRED)\n"
                                        "add_executable(host src/host.cpp)\n"
                                        "install(PROGRAMS scripts/mission.py DESTINATION lib/${PROJECT_NAME})\n")
    (hub / "src" / "host.cpp").write_text((CORPUS_CPP2 / "rclcpp_plugin_host.cpp").read_text())
    (hub / "scripts" / "mission.py").write_text(CLIENT)
    (hub / "scripts" / "mission.py").chmod(0o755)
    result = analyse([tmp_path], [], {}, [])
    holes = [(node, result.store.location(str(hole))[:2]) for hole, node, _why in result.store.rows("plugin_hole")]
    assert holes == [("/controller_host", ("src/hub/src/host.cpp", 31))]
    _ctl, findings = Engine(load_rules([])).run(result.store)
    messages = [f.message for f in findings if f.rule.id == "AL203"]
    assert len(messages) == 1 and "not read at src/hub/src/host.cpp:31" in messages[0]
    assert holes_of(result.store) == [("the pluginlib classes /controller_host creates here (not read)",
                                       "src/hub/src/host.cpp", 31)]
