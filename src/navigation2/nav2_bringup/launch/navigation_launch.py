"""`ros2 launch nav2_bringup navigation_launch.py [use_composition:=False]`: the
controller, smoother, planner, behavior, velocity smoother, collision monitor,
bt_navigator and waypoint follower servers with lifecycle_manager_navigation (Nav2's
navigation_launch.py arguments), as processes of their own or components of the
`container_name` container; the cmd_vel chain is controller_server and behavior_server ->
cmd_vel_nav -> velocity_smoother -> cmd_vel_smoothed -> collision_monitor -> cmd_vel."""

import os

from ament_index_python.packages import get_package_share_directory
from launch.actions import (
    DeclareLaunchArgument,
    GroupAction,
    OpaqueFunction,
    SetEnvironmentVariable,
)
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import PushROSNamespace
from nav2_bringup import nodes

from launch import LaunchDescription


def start(context):
    setup = nodes.Bringup.from_context(context)
    conf = context.launch_configurations
    servers = nodes.built_servers(nodes.NAVIGATION)
    if conf.get('use_composition', 'False').lower() in ('true', '1'):
        described = nodes.components(servers, 'lifecycle_manager_navigation', setup)
        if nodes.gather(context, described):
            return []  # bringup_launch.py starts one container for everything
        return [nodes.container_action(described, conf['container_name'], setup)]
    return nodes.node_actions(servers, 'lifecycle_manager_navigation', setup)


def generate_launch_description():
    bringup_dir = get_package_share_directory('nav2_bringup')
    return LaunchDescription([
        SetEnvironmentVariable('RCUTILS_LOGGING_BUFFERED_STREAM', '1'),
        DeclareLaunchArgument('namespace', default_value='',
                              description='Top-level namespace'),
        DeclareLaunchArgument('use_namespace', default_value='false',
                              description='Whether to apply a namespace to the navigation '
                                          'stack'),
        DeclareLaunchArgument('use_sim_time', default_value='false',
                              description='Use simulation (Gazebo) clock if true'),
        DeclareLaunchArgument(
            'params_file',
            default_value=os.path.join(bringup_dir, 'params', 'nav2_params.yaml'),
            description='Full path to the ROS2 parameters file to use for all launched nodes'),
        DeclareLaunchArgument('autostart', default_value='true',
                              description='Automatically startup the nav2 stack'),
        DeclareLaunchArgument('use_composition', default_value='False',
                              description='Use composed bringup if True'),
        DeclareLaunchArgument('container_name', default_value='nav2_container',
                              description='the name of conatiner that nodes will load in if '
                                          'use composition'),
        DeclareLaunchArgument('use_respawn', default_value='False',
                              description='Whether to respawn if a node crashes. Applied when '
                                          'composition is disabled.'),
        DeclareLaunchArgument('log_level', default_value='info', description='log level'),
        GroupAction([
            PushROSNamespace(LaunchConfiguration('namespace'),
                             condition=IfCondition(LaunchConfiguration('use_namespace'))),
            OpaqueFunction(function=start),
        ]),
    ])
