"""The ports a ROS 2 node has because of its client library (/rosout, /parameter_events, the
parameter services, a lifecycle node's services, ...), from archlog/models/infrastructure/: added
to every ROS 2 node instance, whatever read its source, each marked with the group it belongs to."""

from __future__ import annotations

from archlog import sandbox
from archlog.extract.builtin_ports import Group, builtin
from archlog.extract.launch.model import LaunchNode
from archlog.extract.summary import NodeSummary, Port
from archlog.extract.workspace.index import Workspace


def is_ros2(node: LaunchNode, summary: NodeSummary, workspace: Workspace) -> bool:
    """A ROS 2 node: its source says so (rclpy, rclcpp), else its launch file or package does."""
    if summary.ros:
        return summary.ros == 2
    package = workspace.packages.get(node.pkg)
    return node.ros2 or package is not None and package.ament


def infrastructure_ports(node: LaunchNode, summary: NodeSummary, workspace: Workspace) -> list[Port]:
    """The built-in ports of one instance (none for a ROS 1 node), placed where its code creates the
    node (else at its launch element)."""
    if not is_ros2(node, summary, workspace):
        return []
    table = builtin()
    wanted = [g for g in (*table.default, *summary.infrastructure) if g not in summary.without]
    file, line = (summary.name_file, summary.name_line) if summary.name_file else (node.elem.file, node.elem.line)
    return [Port(kind, name, type_, file, line, infrastructure=group.name)
            for group in (table.groups[g] for g in dict.fromkeys(wanted) if g in table.groups)
            if _released(group, table.distros) for kind, name, type_ in group.ports]


def _released(group: Group, distros: tuple[str, ...]) -> bool:
    """The group exists in the distribution ROS_DISTRO names (one not known, or none: the newest)."""
    distro = sandbox.getenv("ROS_DISTRO") or ""
    if group.since is None or distro not in distros:
        return True
    return distros.index(distro) >= distros.index(group.since)
