"""The effort sensor and the arm guard, configured in the launch file."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="arm_guard", executable="effort_sensor"),
        Node(package="arm_guard", executable="arm_guard",
             parameters=[{"max_effort": 55.0, "joint_count": 9}]),
    ])
