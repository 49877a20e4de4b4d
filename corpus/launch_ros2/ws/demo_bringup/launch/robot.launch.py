from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, SetLaunchConfiguration
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot_name = LaunchConfiguration('robot_name')
    return LaunchDescription([
        DeclareLaunchArgument('robot_name'),
        GroupAction([
            PushRosNamespace(robot_name),
            Node(package='demo_nodes_cpp', executable='talker', name='driver',
                 parameters=[[FindPackageShare('demo_bringup'), '/config/robot.yaml'], {'robot_name': robot_name}]),
        ]),
        SetLaunchConfiguration('last_robot', robot_name),
    ])
