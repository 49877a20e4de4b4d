from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, LaunchConfigurationEquals, LaunchConfigurationNotEquals, UnlessCondition
from launch.substitutions import EnvironmentVariable, LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    lidar = LaunchConfiguration("lidar")
    spinning = PythonExpression(["'", lidar, "' == 'spinning'"])
    return LaunchDescription([
        DeclareLaunchArgument("lidar", default_value=EnvironmentVariable("ROVER_3D_LIDAR")),
        DeclareLaunchArgument("monitor", default_value=EnvironmentVariable("ROVER_MONITOR")),
        Node(package="rover_points", executable="points_driver", name="points_driver",
             condition=IfCondition(spinning), parameters=[{"frame": "spinning_lidar"}]),
        Node(package="rover_points", executable="points_driver", name="points_driver",
             condition=UnlessCondition(spinning), parameters=[{"frame": "solid_state_lidar"}]),
        Node(package="rover_points", executable="cloud_monitor", name="cloud_monitor",
             condition=LaunchConfigurationEquals("monitor", "verbose"),
             parameters=[{"log_every": 1}]),
        Node(package="rover_points", executable="cloud_monitor", name="cloud_monitor",
             condition=LaunchConfigurationNotEquals("monitor", "quiet")),
    ])
