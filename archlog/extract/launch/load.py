"""Which dialect a launch file is written in: ROS 1 XML, or ROS 2 XML, YAML or Python (both XML
dialects use .launch.xml, so a ROS 2 file is told by what it contains), and the ROS 2 executor
with a reader for each ROS 2 dialect."""

from __future__ import annotations

from pathlib import Path

from lxml import etree

from archlog.extract.launch import ros2_frontend, ros2_python
from archlog.extract.launch.model import LaunchHost
from archlog.extract.launch.ros2_actions import PYTHON, XML, YAML
from archlog.extract.launch.ros2_execute import Ros2Launch

_ROS2_TAGS = {"let", "push-ros-namespace", "push_ros_namespace", "set_remap", "set_parameter", "set_env",
              "executable", "node_container", "composable_node", "load_composable_node", "pop-ros-namespace"}
_ROS2_SUBST = ("$(var ", "$(find-pkg-share ", "$(find-pkg-prefix ", "$(find-exec ", "$(exec-in-pkg ")


def ros2_marker(root: etree._Element) -> etree._Element | None:
    """The first element that shows a <launch> file is ROS 2's dialect (both use .launch.xml):
    a ROS 2-only tag, a node with `exec`, or a ROS 2 substitution in an attribute."""
    for el in root.iter():
        if not isinstance(el.tag, str):
            continue
        if el.tag in _ROS2_TAGS or (el.tag == "node" and el.get("exec") is not None) or \
                any("$(" in v and any(marker in v for marker in _ROS2_SUBST) for v in el.attrib.values()):
            return el
    return None


def ros2_by_name(path: Path) -> bool:
    """Whether a file's name alone shows a ROS 2 launch file (Python or YAML)."""
    return path.suffix in (".py", ".yaml", ".yml")


def ros2_launcher(host: LaunchHost) -> Ros2Launch:
    """The ROS 2 executor running into `host`'s configuration, reading each ROS 2 dialect."""
    return Ros2Launch(host, {PYTHON: ros2_python.describe, XML: ros2_frontend.describe_xml,
                             YAML: ros2_frontend.describe_yaml})
