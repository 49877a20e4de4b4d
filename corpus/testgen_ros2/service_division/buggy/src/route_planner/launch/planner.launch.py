"""The route planner alone: its only interface is the plan_route service."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="route_planner", executable="planner", name="planner"),
    ])
