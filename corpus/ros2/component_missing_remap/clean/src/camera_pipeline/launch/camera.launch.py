"""The camera pipeline, composed into one process for zero-copy transport."""

from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode

STAGES = ["driver", "rectifier", "detector"]


def stage(name):
    """One stage of the pipeline as a composable node."""
    plugins = {"driver": "CameraDriver", "rectifier": "Rectifier", "detector": "Detector"}
    remappings = {"rectifier": [("image", "image_raw")],
                  "detector": [("detections", "/perception/detections")]}
    return ComposableNode(
        package="camera_pipeline",
        plugin="camera_pipeline::" + plugins[name],
        name=name,
        namespace="front_camera",
        remappings=remappings.get(name, []),
        extra_arguments=[{"use_intra_process_comms": True}],
    )


def generate_launch_description():
    container = ComposableNodeContainer(
        name="camera_container",
        namespace="front_camera",
        package="rclcpp_components",
        executable="component_container",
        composable_node_descriptions=[stage(name) for name in STAGES],
    )
    return LaunchDescription([container])
