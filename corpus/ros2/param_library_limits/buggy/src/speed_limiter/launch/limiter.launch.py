"""A command source and the speed limiter, configured in the launch file."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="speed_limiter", executable="cmd_source"),
        Node(package="speed_limiter", executable="speed_limiter",
             parameters=[{"max_linear_speed": 5.0, "mode": "brake", "filter.smoothng": 0.3}]),
    ])
