"""The scaler alone."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="scaler", executable="scaler", name="scaler"),
    ])
