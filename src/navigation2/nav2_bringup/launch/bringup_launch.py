"""`ros2 launch nav2_bringup bringup_launch.py map:=<yaml> [use_sim_time:=True]`: Nav2's
localization (localization_launch.py) and navigation (navigation_launch.py) with Nav2's
bringup_launch.py arguments. With use_composition:=True (the default, as upstream) every
server of both is a component of one `nav2_container` process."""

import os

from ament_index_python.packages import PackageNotFoundError, get_package_share_directory
from launch.actions import (
    DeclareLaunchArgument,
    GroupAction,
    IncludeLaunchDescription,
    OpaqueFunction,
    SetEnvironmentVariable,
)
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import PushROSNamespace
from nav2_bringup import nodes

import launch
from launch import LaunchDescription


def composed(context) -> bool:
    return context.launch_configurations['use_composition'].lower() in ('true', '1')


def start_slam(context):
    """slam_launch.py (slam_toolbox, not composed, as upstream) instead of localization."""
    try:
        get_package_share_directory('slam_toolbox')
    except PackageNotFoundError:
        launch.logging.get_logger('launch').warning('slam_toolbox is not built here; left out')
        return []
    conf = context.launch_configurations
    slam_launch = os.path.join(get_package_share_directory('nav2_bringup'), 'launch',
                               'slam_launch.py')
    return [IncludeLaunchDescription(
        PythonLaunchDescriptionSource(slam_launch),
        launch_arguments={name: conf[name] for name in (
            'namespace', 'use_sim_time', 'autostart', 'use_respawn', 'params_file',
            'log_level')}.items())]


def start_gathering(context):
    if composed(context):
        nodes.start_gathering(context)


def start_container(context):
    if not composed(context):
        return []
    described = nodes.stop_gathering(context)
    return [nodes.container_action(described, 'nav2_container',
                                   nodes.Bringup.from_context(context))]


def generate_launch_description():
    launch_dir = os.path.join(get_package_share_directory('nav2_bringup'), 'launch')
    bringup_dir = get_package_share_directory('nav2_bringup')
    conf = {name: LaunchConfiguration(name) for name in (
        'namespace', 'use_namespace', 'slam', 'map', 'use_sim_time', 'params_file',
        'autostart', 'use_composition', 'use_respawn', 'log_level', 'use_localization')}
    common = {name: conf[name] for name in (
        'namespace', 'use_sim_time', 'autostart', 'params_file', 'use_composition',
        'use_respawn', 'log_level')}
    common['container_name'] = 'nav2_container'
    return LaunchDescription([
        SetEnvironmentVariable('RCUTILS_LOGGING_BUFFERED_STREAM', '1'),
        DeclareLaunchArgument('namespace', default_value='',
                              description='Top-level namespace'),
        DeclareLaunchArgument('use_namespace', default_value='false',
                              description='Whether to apply a namespace to the navigation '
                                          'stack'),
        DeclareLaunchArgument('slam', default_value='False', description='Whether run a SLAM'),
        DeclareLaunchArgument('map', default_value='',
                              description='Full path to map yaml file to load'),
        DeclareLaunchArgument('use_localization', default_value='True',
                              description='Whether to enable localization or not'),
        DeclareLaunchArgument('use_sim_time', default_value='false',
                              description='Use simulation (Gazebo) clock if true'),
        DeclareLaunchArgument(
            'params_file',
            default_value=os.path.join(bringup_dir, 'params', 'nav2_params.yaml'),
            description='Full path to the ROS2 parameters file to use for all launched nodes'),
        DeclareLaunchArgument('autostart', default_value='true',
                              description='Automatically startup the nav2 stack'),
        DeclareLaunchArgument('use_composition', default_value='True',
                              description='Whether to use composed bringup'),
        DeclareLaunchArgument('use_respawn', default_value='False',
                              description='Whether to respawn if a node crashes. Applied when '
                                          'composition is disabled.'),
        DeclareLaunchArgument('log_level', default_value='info', description='log level'),
        GroupAction([
            PushROSNamespace(conf['namespace'], condition=IfCondition(conf['use_namespace'])),
            OpaqueFunction(function=start_gathering),
            OpaqueFunction(function=start_slam, condition=IfCondition(PythonExpression(
                [conf['slam'], ' and ', conf['use_localization']]))),
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(launch_dir,
                                                           'localization_launch.py')),
                condition=IfCondition(PythonExpression(
                    ['not ', conf['slam'], ' and ', conf['use_localization']])),
                launch_arguments={**common, 'map': conf['map']}.items()),
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(launch_dir, 'navigation_launch.py')),
                launch_arguments=common.items()),
            OpaqueFunction(function=start_container),
        ]),
    ])
