"""The follower drives the base; both live in the robot's namespace."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    namespace = LaunchConfiguration("namespace")
    simulate = LaunchConfiguration("simulate")
    return LaunchDescription([
        DeclareLaunchArgument("namespace", default_value="bot"),
        DeclareLaunchArgument("simulate", default_value="true"),
        Node(package="drive", executable="path_follower", namespace=namespace,
             parameters=[{"gain": 0.5}]),
        Node(package="drive", executable="diff_drive_base", namespace=namespace,
             condition=IfCondition(simulate)),
    ])
