"""One battery monitor per robot (ForEach over the robots argument), and the dock scheduler, started
with `ros2 run` as a process."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, ForEach, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace


def robot(name=''):
    return [GroupAction([PushRosNamespace(name),
                         Node(package='fleet', executable='battery_monitor', name='battery_monitor')])]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robots', default_value='{name: robot1}; {name: robot2}'),
        ForEach(LaunchConfiguration('robots'), function=robot),
        ExecuteProcess(cmd=['ros2', 'run', 'fleet', 'dock_scheduler']),
    ])
