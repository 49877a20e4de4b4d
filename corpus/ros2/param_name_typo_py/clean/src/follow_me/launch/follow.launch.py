"""The scan filter and the follower, configured from config/follower.yaml."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = os.path.join(get_package_share_directory("follow_me"), "config", "follower.yaml")
    return LaunchDescription([
        Node(package="follow_me", executable="scan_filter", name="scan_filter", parameters=[params]),
        Node(package="follow_me", executable="follower", name="follower", parameters=[params]),
    ])
