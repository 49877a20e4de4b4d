"""The demo system: the same as system.launch.xml and system.launch.yaml."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition, UnlessCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import (EnvironmentVariable, LaunchConfiguration, PathJoinSubstitution,
                                  PythonExpression, ThisLaunchFileDir)
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, Node, PushRosNamespace
from launch_ros.actions import SetParameter, SetRemap
from launch_ros.descriptions import ComposableNode
from launch_ros.substitutions import FindPackageShare


def robot(source, name, condition=None):
    """Include one robot."""
    return IncludeLaunchDescription(PythonLaunchDescriptionSource(source),
                                    launch_arguments={'robot_name': name}.items(), condition=condition)


def talker(name, **kwargs):
    return Node(package='demo_nodes_cpp', executable='talker', name=name, **kwargs)


def generate_launch_description():
    bringup = get_package_share_directory('demo_bringup')
    params_file = os.path.join(bringup, 'config', 'params.yaml')
    robot_file = PathJoinSubstitution([FindPackageShare('demo_bringup'), 'launch', 'robot.launch.py'])
    arguments = [DeclareLaunchArgument(name, default_value=default)
                 for name, default in [('namespace', 'demo'), ('use_sim_time', 'false'), ('with_r2', 'true')]]
    arguments.append(DeclareLaunchArgument('camera', description='whether a camera is attached (no default)'))

    container = ComposableNodeContainer(
        package='rclcpp_components', executable='component_container', name='comp', namespace='containers',
        composable_node_descriptions=[
            ComposableNode(package='composition', plugin='composition::Talker', name='ctalker',
                           parameters=[{'rate': 3}], remappings=[('chatter', 'ctalk')]),
        ])

    ld = LaunchDescription(arguments)
    ld.add_action(SetParameter(name='use_sim_time', value=LaunchConfiguration('use_sim_time')))
    ld.add_action(GroupAction([
        PushRosNamespace(LaunchConfiguration('namespace')),
        SetRemap(src='chatter', dst='talk'),
        talker('talker', parameters=[{'rate': 2, 'qos': {'depth': 5}}, params_file],
               remappings=[('topic', 'chatter')]),
        Node(package='demo_nodes_cpp', executable='listener', name='listener', namespace='sub',
             arguments=['--ros-args', '-r', '__node:=listener2']),
    ]))
    ld.add_action(Node(package='demo_nodes_cpp', executable='listener', name='absolute_listener',
                       namespace='/abs'))
    ld.add_action(robot(robot_file, 'r1'))
    ld.add_action(robot([ThisLaunchFileDir(), '/robot.launch.py'], 'r2',
                        condition=IfCondition(LaunchConfiguration('with_r2'))))
    ld.add_action(talker([LaunchConfiguration('last_robot'), '_monitor']))
    ld.add_action(talker('sim_clock', condition=UnlessCondition(LaunchConfiguration('use_sim_time'))))
    ld.add_action(talker('camera_talker', condition=IfCondition(LaunchConfiguration('camera'))))
    ld.add_action(talker(EnvironmentVariable('ARCHLOG_DEMO_NAME', default_value='env_talker')))
    ld.add_action(talker(PythonExpression(["'eval' + '_talker'"])))
    ld.add_action(container)
    ld.add_action(LoadComposableNodes(target_container='/containers/comp', composable_node_descriptions=[
        ComposableNode(package='composition', plugin='composition::Listener', name='clistener', namespace='cl'),
    ]))
    return ld
