"""The controller manager, its two controllers (the drive's parameters in config/drive.yaml, given
to the spawner with --param-file) and a teleop node that drives the base."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(get_package_share_directory("base_control"), "config")
    return LaunchDescription([
        Node(package="controller_manager", executable="ros2_control_node",
             parameters=[os.path.join(config, "controllers.yaml")]),
        Node(package="controller_manager", executable="spawner", arguments=["joint_state_broadcaster"]),
        Node(package="controller_manager", executable="spawner",
             arguments=["base_controller", "--param-file", os.path.join(config, "drive.yaml"),
                        "--controller-manager", "/controller_manager"]),
        Node(package="base_control", executable="teleop"),
    ])
