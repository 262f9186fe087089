"""`ros2 launch nav2_bringup slam_launch.py`: slam_toolbox's online_sync_launch.py (with the
params file's slam_toolbox section if it has one, else slam_toolbox's own defaults) and
map_saver_server with lifecycle_manager_slam, as Nav2's slam_launch.py."""

import os

import yaml
from ament_index_python.packages import get_package_share_directory
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription, OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node

from launch import LaunchDescription


def has_slam_toolbox_params(params_file: str) -> bool:
    try:
        with open(params_file) as stream:
            content = yaml.safe_load(stream) or {}
    except (OSError, yaml.YAMLError):
        return False
    return isinstance(content, dict) and 'slam_toolbox' in content


def start(context):
    conf = context.launch_configurations
    params_file = conf['params_file']
    use_sim_time = conf['use_sim_time'].lower() in ('true', '1')
    slam_arguments = {'use_sim_time': conf['use_sim_time']}
    if has_slam_toolbox_params(params_file):
        slam_arguments['slam_params_file'] = params_file
    slam_toolbox = os.path.join(get_package_share_directory('slam_toolbox'), 'launch',
                                'online_sync_launch.py')
    return [
        Node(package='nav2_map_server', executable='map_saver_server', output='screen',
             respawn=conf['use_respawn'].lower() in ('true', '1'), respawn_delay=2.0,
             arguments=['--ros-args', '--log-level', conf['log_level']],
             parameters=[params_file, {'use_sim_time': use_sim_time}]),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',
             name='lifecycle_manager_slam', output='screen',
             arguments=['--ros-args', '--log-level', conf['log_level']],
             parameters=[{'use_sim_time': use_sim_time,
                          'autostart': conf['autostart'].lower() in ('true', '1'),
                          'node_names': ['map_saver']}]),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(slam_toolbox),
                                 launch_arguments=slam_arguments.items()),
    ]


def generate_launch_description():
    bringup_dir = get_package_share_directory('nav2_bringup')
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='',
                              description='Top-level namespace'),
        DeclareLaunchArgument(
            'params_file',
            default_value=os.path.join(bringup_dir, 'params', 'nav2_params.yaml'),
            description='Full path to the ROS2 parameters file to use for all launched nodes'),
        DeclareLaunchArgument('use_sim_time', default_value='True',
                              description='Use simulation (Gazebo) clock if true'),
        DeclareLaunchArgument('autostart', default_value='True',
                              description='Automatically startup the nav2 stack'),
        DeclareLaunchArgument('use_respawn', default_value='False',
                              description='Whether to respawn if a node crashes. Applied when '
                                          'composition is disabled.'),
        DeclareLaunchArgument('log_level', default_value='info', description='log level'),
        OpaqueFunction(function=start),
    ])
