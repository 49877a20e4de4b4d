"""IMU driver and state estimator, configured from config/estimation.yaml."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = os.path.join(get_package_share_directory("state_estimation"), "config", "estimation.yaml")
    nodes = [
        Node(package="state_estimation", executable=executable, namespace="robot", parameters=[params])
        for executable in ["imu_driver", "state_estimator"]
    ]
    return LaunchDescription(nodes)
