"""The sequence server alone: its only interface is the fibonacci action."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="sequence_server", executable="sequencer", name="sequencer"),
    ])
