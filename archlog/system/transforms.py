"""Transforms a node broadcasts because of its configuration, not its code: the joints of the robot
description robot_state_publisher reads (fixed joints at once on /tf_static, moving joints once
joint states arrive), the transform static_transform_publisher's command line gives, and those of
the gazebo plugins of the description spawn_model inserts."""

from __future__ import annotations

import shlex
import xml.dom.minidom

from archlog.diagnostics import DiagnosticSink
from archlog.extract.launch.model import LaunchConfig, LaunchNode
from archlog.extract.summary import NodeSummary, Transform
from archlog.extract.workspace.index import Workspace
from archlog.system.robot_description import description, spawned_transforms, where

# robot_state_publisher publishes a moving joint's transform from the joint_states callback
JOINT_STATES = "joint_states"


def spawns(node: LaunchNode) -> bool:
    """gazebo_ros spawn_model: the gazebo plugins of the description it inserts broadcast transforms."""
    return (node.pkg, node.type) == ("gazebo_ros", "spawn_model")


def configured_transforms(node: LaunchNode, summary: NodeSummary, config: LaunchConfig, workspace: Workspace,
                          diagnostics: DiagnosticSink) -> list[Transform] | None:
    """The transforms a node takes from its robot description parameter, its command line or the gazebo
    plugins it spawns; None when they cannot be known statically (then it may broadcast any transform)."""
    found: list[Transform] = []
    spawned = spawned_transforms(node, shlex.split(node.args), config, workspace, diagnostics) \
        if spawns(node) else []
    for part in (_joints(node, summary.tf_description, config, workspace, diagnostics) if summary.tf_description
                 else [], _from_args(node, diagnostics) if summary.tf_args else [], spawned):
        if part is None:
            return None
        found += part
    return found


def _joints(node: LaunchNode, param: str, config: LaunchConfig, workspace: Workspace,
            diagnostics: DiagnosticSink) -> list[Transform] | None:
    """One transform per joint of the description, parent link -> child link."""
    urdf = description(param, node, config, workspace, diagnostics)
    if urdf is None:
        return None
    transforms = []
    for joint in urdf.doc.getElementsByTagName("joint"):
        links = [next((e.getAttribute("link") for e in joint.childNodes
                       if isinstance(e, xml.dom.minidom.Element) and e.tagName == tag), "") for tag in ("parent", "child")]
        if not all(links) or getattr(joint.parentNode, "tagName", "") != "robot":
            continue  # a transmission's <joint> (no links), or one nested in another element
        file, line = where(f'"{joint.getAttribute("name")}"', urdf.files, urdf.elem, workspace)
        after = () if joint.getAttribute("type") == "fixed" else (JOINT_STATES,)
        transforms.append(Transform(links[0], links[1], file, line, after))
    return transforms


def _from_args(node: LaunchNode, diagnostics: DiagnosticSink) -> list[Transform] | None:
    """static_transform_publisher x y z yaw pitch roll FRAME CHILD [period], or with a quaternion
    x y z qx qy qz qw FRAME CHILD [period] (tf's version takes the period in milliseconds)."""
    try:
        words = [w for w in shlex.split(node.args) if ":=" not in w]
    except ValueError:
        words = []
    numbers = 0
    while numbers < len(words) and _is_number(words[numbers]):
        numbers += 1
    if numbers not in (6, 7) or len(words) < numbers + 2:
        diagnostics.add(node.elem.file, node.elem.line, "tf-args",
                        f"{node.name}: the arguments '{node.args}' are not 'x y z yaw pitch roll frame child' nor "
                        "'x y z qx qy qz qw frame child'; the transform it broadcasts is unknown")
        return None
    return [Transform(words[numbers], words[numbers + 1], node.elem.file, node.elem.line)]


def _is_number(word: str) -> bool:
    try:
        float(word)
    except ValueError:
        return False
    return True
