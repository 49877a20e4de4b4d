"""The robot's lidar and the obstacle monitor that watches its scans."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    robot = LaunchConfiguration("robot")
    return LaunchDescription([
        DeclareLaunchArgument("robot", default_value="rover"),
        GroupAction([
            PushRosNamespace(robot),
            Node(package="lidar_driver", executable="lidar_node", name="front_lidar",
                 parameters=[{"frame_id": "front_laser"}],
                 remappings=[("scan", "front/scan")]),
            Node(package="obstacle_monitor", executable="monitor",
                 parameters=[{"stop_distance": 0.4}]),
        ]),
    ])
