"""Ports that a robot description creates: the gazebo_ros plugins in its `<gazebo>` elements.

The description is a parameter set from a URDF text (`textfile=`) or from a `command=` that runs
xacro; xacro files are expanded with the xacro library routed through archlog's restricted evaluator,
sandboxed reading and budgets (see `xacro_expand`; nothing in them is run), with `$(find pkg)`
answered from the workspace. The plugins run inside gzserver once
`spawn_model -param NAME` inserts the model, so their ports are given to that spawn_model instance.
"""

from __future__ import annotations

import shlex
import xml.dom.minidom
from dataclasses import dataclass
from pathlib import Path

from archlog import names, sandbox
from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import Element, LaunchConfig, LaunchNode
from archlog.extract.summary import Port
from archlog.extract.workspace.index import Workspace
from archlog.system.command_line import split_options
from archlog.system.xacro_expand import Place, XacroFailure, expand, parse_xml
from archlog.values import Unknown


@dataclass(frozen=True)
class PluginTopic:
    kind: str  # publisher or subscriber
    element: str  # the plugin's SDF element naming the topic
    default: str | None  # the plugin's default when the element is absent (None: no default)
    type: str


DRIVE = (PluginTopic("subscriber", "commandTopic", "cmd_vel", "geometry_msgs/Twist"),
         PluginTopic("publisher", "odometryTopic", "odom", "nav_msgs/Odometry"))
PLUGINS: dict[str, tuple[PluginTopic, ...]] = {
    "libgazebo_ros_diff_drive.so": DRIVE,
    "libgazebo_ros_skid_steer_drive.so": DRIVE,
    "libgazebo_ros_planar_move.so": DRIVE,
    "libgazebo_ros_imu.so": (PluginTopic("publisher", "topicName", None, "sensor_msgs/Imu"),),
    "libgazebo_ros_imu_sensor.so": (PluginTopic("publisher", "topicName", None, "sensor_msgs/Imu"),),
    "libgazebo_ros_laser.so": (PluginTopic("publisher", "topicName", None, "sensor_msgs/LaserScan"),),
    "libgazebo_ros_gpu_laser.so": (PluginTopic("publisher", "topicName", None, "sensor_msgs/LaserScan"),),
    "libgazebo_ros_p3d.so": (PluginTopic("publisher", "topicName", None, "nav_msgs/Odometry"),),
    "libgazebo_ros_joint_state_publisher.so": (PluginTopic("publisher", "topicName", "joint_states",
                                                           "sensor_msgs/JointState"),),
    "libgazebo_ros_camera.so": (PluginTopic("publisher", "imageTopicName", "image_raw", "sensor_msgs/Image"),
                                PluginTopic("publisher", "cameraInfoTopicName", "camera_info",
                                            "sensor_msgs/CameraInfo")),
    "libgazebo_ros_control.so": (),  # its controllers come from controller_manager's configuration
}


def spawned_ports(node: LaunchNode, words: list[str], config: LaunchConfig, workspace: Workspace,
                  diagnostics: DiagnosticSink) -> list[Port]:
    """The plugin ports of the description `spawn_model -urdf -param NAME` inserts."""
    _positional, option = split_options(words, {"-param", "-robot_namespace"})
    if "-param" not in option:
        return []
    key = names.canonical(names.resolve(option["-param"], node.namespace, node.name))
    if key not in config.params:
        diagnostics.add(node.elem.file, node.elem.line, "robot-description",
                        f"spawn_model reads {key}, which this configuration does not set", "warning")
        return []
    value, elem = config.params[key]
    described = _expand(value, elem, workspace, diagnostics)
    if described is None:
        return []
    text, files = described
    try:
        doc = parse_xml(text)
    except Exception as exc:  # expat raises several types for broken XML
        diagnostics.add(elem.file, elem.line, "robot-description", f"robot description is not XML: {exc}", "warning")
        return []
    return [port for plugin in doc.getElementsByTagName("plugin")
            for port in _plugin_ports(plugin, option.get("-robot_namespace"), files, elem, workspace, diagnostics)]


def _expand(value: object, elem: Element, workspace: Workspace,
            diagnostics: DiagnosticSink) -> tuple[str, list[Path]] | None:
    """The description's XML text and the files it came from."""
    if isinstance(value, str):
        return value, []
    expr = value.expr if isinstance(value, Unknown) else ""
    try:
        words = shlex.split(expr[len("command: "):]) if expr.startswith("command: ") else []
    except ValueError:  # unbalanced quotes: reported below as a description not known statically
        words = []
    program = next((i for i, w in enumerate(words) if Path(w).name in ("xacro", "xacro.py")), None)
    source = next((w for w in words[(program or 0) + 1:] if ":=" not in w and not w.startswith("-")), None)
    if program is None or source is None:
        diagnostics.add(elem.file, elem.line, "robot-description",
                        f"robot description not known statically ({expr or value}); its gazebo plugins are not read",
                        "note")
        return None
    mappings = dict(w.split(":=", 1) for w in words[program + 1:] if ":=" in w and not w.startswith("_"))
    return _xacro(Path(source), mappings, workspace, elem, diagnostics)


def _xacro(source: Path, mappings: dict[str, str], workspace: Workspace, elem: Element,
           diagnostics: DiagnosticSink) -> tuple[str, list[Path]] | None:
    def at(place: Place) -> tuple[str, int]:
        file, line = place
        return (workspace.display(file), line or 1) if file else (elem.file, elem.line)

    try:
        expanded = expand(source, mappings, workspace.find)
    except XacroFailure as failure:
        for name, place in failure.unseen:
            diagnostics.add(*at(place), "env-not-given", sandbox.not_given_message(name))
        diagnostics.add(*at(failure.place), failure.code, str(failure))
        return None
    for name, place in expanded.unseen:
        diagnostics.add(*at(place), "env-not-given", sandbox.not_given_message(name))
    return expanded.text, expanded.files


def _plugin_ports(plugin: xml.dom.minidom.Element, robot_ns: str | None, files: list[Path], elem: Element,
                  workspace: Workspace, diagnostics: DiagnosticSink) -> list[Port]:
    library = plugin.getAttribute("filename")
    file, line = _where(library, files, elem, workspace)
    if library not in PLUGINS:
        if library.startswith("libgazebo_ros"):
            diagnostics.add(file, line, "robot-description", f"gazebo plugin {library} is not modelled; "
                                                               "its topics are unknown", "note")
        return []
    ns = robot_ns if robot_ns is not None else _text(plugin, "robotNamespace") or ""
    if library == "libgazebo_ros_camera.so":
        ns = names.join("/" + ns.strip("/"), _text(plugin, "cameraName") or "")
    ports = []
    for topic in PLUGINS[library]:
        name = _text(plugin, topic.element) or topic.default
        resolved: str | Unknown = names.resolve(name, "/" + ns.strip("/"), "/gazebo") if name else \
            Unknown(f"{library} without <{topic.element}>", file, line)
        ports.append(Port(topic.kind, resolved, topic.type, file, line))
    return ports


def _text(plugin: xml.dom.minidom.Element, tag: str) -> str | None:
    found = [e for e in plugin.childNodes if getattr(e, "tagName", None) == tag]
    return "".join(n.data for n in found[0].childNodes if n.nodeType == n.TEXT_NODE).strip() if found else None


def _where(library: str, files: list[Path], elem: Element, workspace: Workspace) -> tuple[str, int]:
    """The line naming the plugin in the description's files, else the launch element."""
    for path in files:
        try:
            for number, line in enumerate(sandbox.read_text(path, "description").splitlines(), 1):
                if f'"{library}"' in line:
                    return workspace.display(path), number
        except sandbox.Refused:
            continue
    return elem.file, elem.line
