"""Wheel odometry and the fuser, configured in the launch file."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="odom_fusion", executable="wheel_odometry"),
        Node(package="odom_fusion", executable="odom_fuser",
             parameters=[{"input_topics": "wheel/odom", "smoothing": 0.5}]),
    ])
