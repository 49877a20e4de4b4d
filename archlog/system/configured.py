"""Ports that come from a node's command line and the files it names, not from its code:
`rosbag record` subscribes to the topics it is given, rviz to what its displays (`-d FILE`) name
and publishes from its tools, and `spawn_model` brings the gazebo plugins of the robot description."""

from __future__ import annotations

import shlex
from pathlib import Path

import yaml

from archlog import budget, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import LaunchConfig, LaunchNode
from archlog.extract.summary import Port
from archlog.extract.workspace.index import Workspace
from archlog.system.command_line import split_options
from archlog.system.node_models import LineLoader
from archlog.system.robot_description import spawned_ports
from archlog.values import Unknown

# rosbag record options that take a value (the next word is not a topic)
_RECORD_VALUED = {"-O", "-o", "--output-name", "--output-prefix", "-x", "--exclude", "--size", "--duration", "-b",
                  "--buffsize", "--chunksize", "-l", "--limit", "--node", "--max-splits"}
RVIZ_TYPES = {
    "rviz/LaserScan": "sensor_msgs/LaserScan", "rviz/Image": "sensor_msgs/Image", "rviz/Camera": "sensor_msgs/Image",
    "rviz/Map": "nav_msgs/OccupancyGrid", "rviz/Path": "nav_msgs/Path", "rviz/Odometry": "nav_msgs/Odometry",
    "rviz/PointCloud2": "sensor_msgs/PointCloud2", "rviz/PointCloud": "sensor_msgs/PointCloud",
    "rviz/Marker": "visualization_msgs/Marker", "rviz/MarkerArray": "visualization_msgs/MarkerArray",
    "rviz/Pose": "geometry_msgs/PoseStamped", "rviz/PoseArray": "geometry_msgs/PoseArray",
    "rviz/PoseWithCovariance": "geometry_msgs/PoseWithCovarianceStamped",
    "rviz/Polygon": "geometry_msgs/PolygonStamped",
    "rviz/Range": "sensor_msgs/Range", "rviz/Temperature": "sensor_msgs/Temperature",
    "rviz/Illuminance": "sensor_msgs/Illuminance", "rviz/Wrench": "geometry_msgs/WrenchStamped",
    "rviz/Imu": "sensor_msgs/Imu", "rviz_imu_plugin/Imu": "sensor_msgs/Imu",
    "rviz/SetGoal": "geometry_msgs/PoseStamped", "rviz/SetInitialPose": "geometry_msgs/PoseWithCovarianceStamped",
    "rviz/PublishPoint": "geometry_msgs/PointStamped",
}
RVIZ_TOOL_TOPICS = {"rviz/SetGoal": "/move_base_simple/goal", "rviz/SetInitialPose": "/initialpose",
                    "rviz/PublishPoint": "/clicked_point"}


def configured_ports(node: LaunchNode, config: LaunchConfig, workspace: Workspace,
                     diagnostics: DiagnosticSink) -> tuple[list[Port], str | None]:
    """The ports a node's command line configures, and why they may not be all (None: they are)."""
    words = shlex.split(node.args) if node.args else []
    if (node.pkg, node.type) == ("gazebo_ros", "spawn_model"):
        return spawned_ports(node, words, config, workspace, diagnostics)
    if (node.pkg, node.type) == ("rosbag", "record"):
        return _recorded(node, words), None
    if (node.pkg, node.type) == ("rviz", "rviz"):
        display = next((words[i + 1] for i, w in enumerate(words[:-1]) if w in ("-d", "--display-config")), None)
        return (_rviz(node, Path(display), diagnostics) if display else []), None
    return [], None


def _recorded(node: LaunchNode, words: list[str]) -> list[Port]:
    """The topics `rosbag record` is given (none are known with -a or with -e regexes)."""
    if {"-a", "--all", "-e", "--regex"} & set(words):
        return []
    topics, _options = split_options(words, _RECORD_VALUED)
    return [Port("subscriber", topic, Unknown(f"rosbag records {topic} whatever its type", node.elem.file,
                                              node.elem.line), node.elem.file, node.elem.line) for topic in topics]


def _rviz(node: LaunchNode, config: Path, diagnostics: DiagnosticSink) -> list[Port]:
    try:
        data = yaml.load(sandbox.read_text(config, "config"), Loader=LineLoader)
    except sandbox.Refused as exc:
        diagnostics.add(node.elem.file, node.elem.line, exc.code,
                        f"rviz configuration not read ({exc}); its displays' topics are unknown", "warning")
        return []
    except budget.BudgetExceeded as exc:
        diagnostics.add(node.elem.file, node.elem.line, "budget-exceeded",
                        f"rviz configuration {config}: {exc}; its displays' topics are unknown", "error")
        return []
    except yaml.YAMLError as exc:
        diagnostics.add(node.elem.file, node.elem.line, "rviz-config",
                        f"rviz configuration {config} cannot be read ({exc}); its displays' topics are unknown",
                        "warning")
        return []
    manager = _mapping(data.get("Visualization Manager") if isinstance(data, dict) else None)
    shown = str(config)
    ports = [port for display in _displays(manager.get("Displays"))
             if (port := _display_port(display, shown, diagnostics))]
    tools = manager.get("Tools")
    for tool in tools if isinstance(tools, list) else []:
        kind = _text(tool.get("Class"), tool, shown, diagnostics) if isinstance(tool, dict) else None
        if kind in RVIZ_TOOL_TOPICS:
            topic = _text(tool.get("Topic", RVIZ_TOOL_TOPICS[kind]), tool, shown, diagnostics)
            if topic:
                ports.append(Port("publisher", topic, RVIZ_TYPES[kind], shown, tool["__line__"]))
    return ports


def _mapping(value: object) -> dict:
    return value if isinstance(value, dict) else {}


def _text(value: object, entry: dict, shown: str, diagnostics: DiagnosticSink) -> str | None:
    """A display's or tool's Class or Topic: a string (or a number, as rviz reads it), else None
    with a diagnostic at the entry."""
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return str(value)
    diagnostics.add(shown, entry.get("__line__", 1), "rviz-config",
                    f"expected a name here, found a {type(value).__name__}; this entry is not read", "warning")
    return None


def _displays(displays: object) -> list[dict]:
    """Enabled displays, with those inside display groups, in file order (walked without recursion)."""
    found: list[dict] = []
    pending = list(reversed(displays)) if isinstance(displays, list) else []
    while pending:
        display = pending.pop()
        if isinstance(display, dict) and display.get("Enabled") is not False:
            found.append(display)
            children = display.get("Displays")
            if isinstance(children, list):
                pending += reversed(children)
    return found


def _display_port(display: dict, shown: str, diagnostics: DiagnosticSink) -> Port | None:
    topic = display.get("Topic") or display.get("Image Topic") or display.get("Marker Topic")
    if isinstance(topic, dict):
        topic = topic.get("Value")
    topic = _text(topic, display, shown, diagnostics)
    kind = _text(display.get("Class", ""), display, shown, diagnostics) if topic else None
    if not topic or kind is None:
        return None
    line = display.get("__line__", 1)
    type_ = RVIZ_TYPES.get(kind) or Unknown(f"rviz display {kind}", shown, line)
    return Port("subscriber", topic, type_, shown, line)
