"""Generators for hostile inputs that grow with a size: each returns the files of a workspace (paths
from its root) and the launch file to check. The tests grow the size until the budget stops it;
run as a script, it writes the full-size workspaces and times `archlog check` on each:

    python tests/support/hostile_classes.py OUT_DIR [CLASS ...]
"""

from __future__ import annotations

import json
import resource
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

Files = dict[str, str]

ROS1_PACKAGE = """<package format="2"><name>demo</name><version>0.0.0</version><description>demo</description>
<maintainer email="demo@example.com">demo</maintainer><license>MIT</license>
<buildtool_depend>catkin</buildtool_depend><depend>roscpp</depend><depend>rospy</depend></package>
"""
ROS2_PACKAGE = """<package format="3"><name>demo</name><version>0.0.0</version><description>demo</description>
<maintainer email="demo@example.com">demo</maintainer><license>MIT</license>
<buildtool_depend>ament_cmake</buildtool_depend><depend>rclcpp</depend><depend>std_msgs</depend>
<export><build_type>ament_cmake</build_type></export></package>
"""
TALKER = """#!/usr/bin/env python
import rospy
from std_msgs.msg import String
rospy.init_node('talker')
pub = rospy.Publisher('chatter', String, queue_size=1)
sub = rospy.Subscriber('heard', String, lambda m: None)
"""


def _ros1(cmake: str, launch_body: str = '  <node pkg="demo" type="talker.py" name="talker"/>\n') -> Files:
    """A ROS 1 package whose CMakeLists.txt is `cmake`, with a rospy talker and a launch file."""
    return {"demo/package.xml": ROS1_PACKAGE, "demo/CMakeLists.txt": cmake, "demo/scripts/talker.py": TALKER,
            "demo/launch/demo.launch": f"<launch>\n{launch_body}</launch>\n"}


CMAKE_HEAD = "cmake_minimum_required(VERSION 3.0)\nproject(demo)\nfind_package(catkin REQUIRED)\n"


def cmake_brackets(count: int) -> Files:
    """`count` bracket arguments `[[` that are never closed (each could close anywhere after it)."""
    return _ros1(CMAKE_HEAD + "".join(f"set(A{i} [[x{i})\n" for i in range(count)))


def cmake_bracket_comments(count: int) -> Files:
    """`count` bracket comments `#[[` that are never closed."""
    return _ros1(CMAKE_HEAD + "".join(f"#[[ comment {i}\nset(A{i} x)\n" for i in range(count)))


def cmake_self_subdirectory(count: int) -> Files:
    """A CMakeLists.txt adding its own folder `count` times: count**depth readings without a cut."""
    return _ros1(CMAKE_HEAD + "add_executable(node src/node.cpp)\n" + "add_subdirectory(.)\n" * count)


def cpp_concatenation(parts: int, choices: int = 6) -> Files:
    """A rclcpp node whose topic is `parts` strings added together, each assigned one of `choices`
    values (choices**parts combinations), plus an honest publisher."""
    lines = ['#include "rclcpp/rclcpp.hpp"', '#include "std_msgs/msg/string.hpp"', "",
             "int main(int argc, char ** argv)", "{", "  rclcpp::init(argc, argv);",
             '  auto node = rclcpp::Node::make_shared("talker");']
    for p in range(parts):
        lines.append(f'  std::string p{p} = "p{p}";')
        lines += [f'  if (argc == {c}) {{p{p} = "p{p}_{c}";}}' for c in range(choices - 1)]
    topic = " + ".join(f"p{p}" for p in range(parts))
    lines += [f"  auto a = node->create_publisher<std_msgs::msg::String>({topic}, 10);",
              '  auto b = node->create_publisher<std_msgs::msg::String>("honest", 10);',
              "  rclcpp::spin(node);", "}"]
    cmake = ("cmake_minimum_required(VERSION 3.5)\nproject(demo)\nfind_package(ament_cmake REQUIRED)\n"
             "find_package(rclcpp REQUIRED)\nadd_executable(talker src/talker.cpp)\n"
             "install(TARGETS talker DESTINATION lib/${PROJECT_NAME})\nament_package()\n")
    return {"demo/package.xml": ROS2_PACKAGE, "demo/CMakeLists.txt": cmake, "demo/src/talker.cpp": "\n".join(lines) + "\n",
            "demo/launch/demo.launch.xml": '<launch>\n  <node pkg="demo" exec="talker" name="talker"/>\n</launch>\n'}


def python_dag(levels: int) -> Files:
    """A ROS 2 Python launch function returning a DAG of actions: each level a group holding the
    level below twice (2**levels paths to the node at the bottom)."""
    body = ["from launch import LaunchDescription", "from launch.actions import GroupAction",
            "from launch_ros.actions import Node", "", "", "def generate_launch_description():",
            "    level = [Node(package='demo', executable='talker', name='talker')]"]
    body += ["    level = [GroupAction(level), GroupAction(level)]"] * levels
    body += ["    return LaunchDescription(level)"]
    return {"demo/package.xml": ROS2_PACKAGE.replace("ament_cmake", "ament_python"),
            "demo/launch/demo.launch.py": "\n".join(body) + "\n"}


def xml_include_fan(levels: int) -> Files:
    """ROS 2 XML launch files each including the next twice, `levels` deep; the last one starts a node."""
    files = {"demo/package.xml": ROS2_PACKAGE.replace("ament_cmake", "ament_python")}
    for i in range(levels):
        include = f'  <include file="$(dirname)/l{i + 1}.launch.xml"/>\n'
        files[f"demo/launch/l{i}.launch.xml"] = f"<launch>\n{include * 2}</launch>\n"
    files[f"demo/launch/l{levels}.launch.xml"] = ('<launch>\n  <node pkg="demo" exec="talker" name="talker"/>\n'
                                                 "</launch>\n")
    files["demo/launch/demo.launch.xml"] = files.pop("demo/launch/l0.launch.xml")
    return files


def ros1_remapped(nodes: int) -> Files:
    """A ROS 1 launch file with `nodes` talkers, each in its own namespace under its own name (two
    distinct name segments a node), each remapping its topics to names of its own."""
    body = "".join(f'  <node pkg="demo" type="talker.py" name="n{i}" ns="s{i}">\n'
                   f'    <remap from="chatter" to="/out/c{i}"/>\n    <remap from="heard" to="/out/c{i + 1}"/>\n'
                   "  </node>\n" for i in range(nodes))
    return _ros1(CMAKE_HEAD, body)


def ros1_remapped_dangling(nodes: int) -> Files:
    """As `ros1_remapped`, but no two nodes connect: each publishes a name of its own nobody hears and
    hears a name of its own nobody publishes (one message type: every publisher is a candidate
    counterpart of every subscriber, for AL103 and AL104 and the near-miss search)."""
    body = "".join(f'  <node pkg="demo" type="talker.py" name="n{i}" ns="s{i}">\n'
                   f'    <remap from="chatter" to="/out/c{i}"/>\n    <remap from="heard" to="/in/h{i}"/>\n'
                   "  </node>\n" for i in range(nodes))
    return _ros1(CMAKE_HEAD, body)


FULL: dict[str, tuple[Callable[[int], Files], int]] = {
    "cmake_brackets": (cmake_brackets, 100_000),
    "cmake_bracket_comments": (cmake_bracket_comments, 100_000),
    "cmake_self_subdirectory": (cmake_self_subdirectory, 10),
    "cpp_concatenation": (cpp_concatenation, 12),
    "python_dag": (python_dag, 40),
    "xml_include_fan": (xml_include_fan, 30),
    "ros1_remapped": (ros1_remapped, 20_000),
    "ros1_remapped_dangling": (ros1_remapped_dangling, 20_000),
}
"""Each class at the size of the report that found it."""


def launch_of(files: Files) -> str:
    return next(p for p in files if p.startswith("demo/launch/demo.launch"))


def write(root: Path, files: Files) -> None:
    for path, text in files.items():
        (root / path).parent.mkdir(parents=True, exist_ok=True)
        (root / path).write_text(text)
        if text.startswith("#!"):
            (root / path).chmod(0o755)


LIMIT = 60
"""CPU seconds a check may take (wall time is no measure on a machine shared with other work); it is
stopped after ten times as many seconds of wall time in any case."""


def _cpu_limit() -> None:
    resource.setrlimit(resource.RLIMIT_CPU, (LIMIT, LIMIT))


def main() -> None:
    out = Path(sys.argv[1])
    for name in sys.argv[2:] or list(FULL):
        generate, size = FULL[name]
        files = generate(size)
        write(out / name, files)
        begin = time.monotonic()
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        command = [sys.executable, "-m", "archlog", "check", str(out / name), "--launch",
                   str(out / name / launch_of(files)), "--format", "json", "--fail-on", "never"]
        try:
            done = subprocess.run(command, capture_output=True, text=True, timeout=10 * LIMIT, preexec_fn=_cpu_limit)
        except subprocess.TimeoutExpired:
            print(f"{name} size {size}: killed at {10 * LIMIT} s wall", flush=True)
            continue
        if done.returncode < 0:
            print(f"{name} size {size}: killed by signal {-done.returncode} (CPU limit {LIMIT} s)", flush=True)
            continue
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
        report = json.loads(done.stdout[done.stdout.index("{"):])
        budget = [f"{d['file']}:{d['line']}" for d in report["diagnostics"] if d["code"] == "budget-exceeded"]
        print(f"{name} size {size}: {time.monotonic() - begin:.1f} s wall, {cpu:.1f} s CPU, "
              f"{after.ru_maxrss / 1024:.0f} MB max RSS, exit {done.returncode}, "
              f"budget-exceeded at {budget[:3]}, {len(report['findings'])} findings", flush=True)


if __name__ == "__main__":
    main()
