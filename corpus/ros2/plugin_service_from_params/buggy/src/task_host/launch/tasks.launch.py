import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = os.path.join(get_package_share_directory('task_host'), 'config', 'tasks.yaml')
    return LaunchDescription([
        Node(package='task_host', executable='task_server', namespace='robot', parameters=[params]),
        Node(package='task_client', executable='dock_client', namespace='robot'),
    ])
