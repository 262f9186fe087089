"""`ros2 launch nav2_bringup rviz_launch.py`: the RViz page (rqt_web's `rviz2`) with
nav2_default_view.rviz, as Nav2's rviz_launch.py; the launch ends when it exits."""

import os

from ament_index_python.packages import get_package_share_directory
from launch.actions import DeclareLaunchArgument, EmitEvent, RegisterEventHandler
from launch.conditions import IfCondition, UnlessCondition
from launch.event_handlers import OnProcessExit
from launch.events import Shutdown
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

from launch import LaunchDescription


def generate_launch_description():
    bringup_dir = get_package_share_directory('nav2_bringup')
    namespace = LaunchConfiguration('namespace')
    use_namespace = LaunchConfiguration('use_namespace')
    rviz_config = LaunchConfiguration('rviz_config')
    use_sim_time = LaunchConfiguration('use_sim_time')
    plain = Node(package='rviz2', executable='rviz2', arguments=['-d', rviz_config],
                 output='screen', parameters=[{'use_sim_time': use_sim_time}],
                 condition=UnlessCondition(use_namespace))
    namespaced = Node(package='rviz2', executable='rviz2', namespace=namespace,
                      arguments=['-d', rviz_config], output='screen',
                      parameters=[{'use_sim_time': use_sim_time}],
                      remappings=[('/map', 'map'), ('/tf', 'tf'), ('/tf_static', 'tf_static'),
                                  ('/goal_pose', 'goal_pose'), ('/clicked_point',
                                                                'clicked_point'),
                                  ('/initialpose', 'initialpose')],
                      condition=IfCondition(use_namespace))
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='navigation',
                              description='Top-level namespace. The value will be used to '
                                          'replace the <robot_namespace> keyword on the rviz '
                                          'config file.'),
        DeclareLaunchArgument('use_namespace', default_value='false',
                              description='Whether to apply a namespace to the navigation '
                                          'stack'),
        DeclareLaunchArgument(
            'rviz_config', default_value=os.path.join(bringup_dir, 'rviz',
                                                      'nav2_default_view.rviz'),
            description='Full path to the RVIZ config file to use'),
        DeclareLaunchArgument('use_sim_time', default_value='false',
                              description='Use simulation (Gazebo) clock if true'),
        plain, namespaced,
        RegisterEventHandler(OnProcessExit(
            target_action=plain, on_exit=[EmitEvent(event=Shutdown(reason='rviz exited'))])),
        RegisterEventHandler(OnProcessExit(
            target_action=namespaced,
            on_exit=[EmitEvent(event=Shutdown(reason='rviz exited'))])),
    ])
