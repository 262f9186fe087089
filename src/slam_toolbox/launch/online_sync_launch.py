"""Online sync SLAM: slam_toolbox's sync_slam_toolbox_node as a lifecycle node, with
slam_toolbox Jazzy's launch arguments. With autostart (and no lifecycle manager) the launch
itself configures the node and, once it is inactive, activates it."""

import os

from ament_index_python.packages import get_package_share_directory
from launch.actions import DeclareLaunchArgument, EmitEvent, LogInfo, RegisterEventHandler
from launch.conditions import IfCondition
from launch.events import matches_action
from launch.substitutions import AndSubstitution, LaunchConfiguration, NotSubstitution
from launch_ros.actions import LifecycleNode
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition

from launch import LaunchDescription


def generate_launch_description():
    autostart = LaunchConfiguration('autostart')
    use_lifecycle_manager = LaunchConfiguration('use_lifecycle_manager')
    default_params = os.path.join(get_package_share_directory('slam_toolbox'), 'config',
                                  'mapper_params_online_sync.yaml')
    slam = LifecycleNode(
        package='slam_toolbox', executable='sync_slam_toolbox_node', name='slam_toolbox',
        namespace='', output='screen',
        parameters=[LaunchConfiguration('slam_params_file'),
                    {'use_lifecycle_manager': use_lifecycle_manager,
                     'use_sim_time': LaunchConfiguration('use_sim_time')}])
    # the launch drives the transitions only when nothing else will
    by_launch = IfCondition(AndSubstitution(autostart, NotSubstitution(use_lifecycle_manager)))
    configure = EmitEvent(
        event=ChangeState(lifecycle_node_matcher=matches_action(slam),
                          transition_id=Transition.TRANSITION_CONFIGURE),
        condition=by_launch)
    activate_when_configured = RegisterEventHandler(
        OnStateTransition(
            target_lifecycle_node=slam, start_state='configuring', goal_state='inactive',
            entities=[
                LogInfo(msg='[LifecycleLaunch] Slamtoolbox node is activating.'),
                EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(slam),
                                            transition_id=Transition.TRANSITION_ACTIVATE)),
            ]),
        condition=by_launch)
    return LaunchDescription([
        DeclareLaunchArgument('autostart', default_value='true',
                              description='Automatically startup the slamtoolbox. Ignored '
                                          'when use_lifecycle_manager is true.'),
        DeclareLaunchArgument('use_lifecycle_manager', default_value='false',
                              description='Enable bond connection during node activation'),
        DeclareLaunchArgument('use_sim_time', default_value='true',
                              description='Use simulation/Gazebo clock'),
        DeclareLaunchArgument('slam_params_file', default_value=default_params,
                              description='Full path to the ROS2 parameters file to use for '
                                          'the slam_toolbox node'),
        slam,
        configure,
        activate_when_configured,
    ])
