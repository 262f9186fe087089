"""`ros2 launch nav2_bringup tb3_simulation_launch.py [headless:=True] [use_rviz:=False]`:
Nav2's all-in-one simulation launch with its arguments, on this workspace's simulator: the
MuJoCo warehouse world with the diffbot (diffbot_bringup's diffbot_sim.launch.py: the
simulator on /clock, robot_state_publisher) instead of Gazebo and the TurtleBot3, Nav2
(bringup_launch.py) on the warehouse map, and the RViz page (rviz_launch.py).

The robot starts at (x_pose, y_pose, yaw) = (0, 0, 0): the warehouse's start, where
nav2_simple_commander's examples set their initial pose (upstream's TB3 sandbox starts at
(-2.0, -0.5)). `world` is a file of mujoco_sim's worlds/ or an absolute path; robot_name,
robot_sdf, z_pose, roll and pitch are accepted and unused (the diffbot is the one robot), and
headless has nothing to hide (the simulator has no window)."""

import os

from ament_index_python.packages import get_package_share_directory
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare

from launch import LaunchDescription

ARGUMENTS = (
    ('namespace', '', 'Top-level namespace'),
    ('use_namespace', 'false', 'Whether to apply a namespace to the navigation stack'),
    ('slam', 'False', 'Whether run a SLAM'),
    ('use_sim_time', 'true', 'Use simulation (Gazebo) clock if true'),
    ('autostart', 'true', 'Automatically startup the nav2 stack'),
    ('use_composition', 'True', 'Whether to use composed bringup'),
    ('use_respawn', 'False',
     'Whether to respawn if a node crashes. Applied when composition is disabled.'),
    ('use_simulator', 'True', 'Whether to start the simulator'),
    ('use_robot_state_pub', 'True', 'Whether to start the robot state publisher'),
    ('use_rviz', 'True', 'Whether to start RVIZ'),
    ('headless', 'True', 'Whether to execute gzclient)'),
    ('world', 'warehouse.xml', "World file (MJCF) in mujoco_sim's worlds/, or a full path"),
    ('robot_name', 'turtlebot3_waffle', 'name of the robot'),
    ('robot_sdf', '', 'Full path to robot sdf file to spawn the robot in gazebo (unused)'),
    ('x_pose', '0.00', 'Start x in the world, m'),
    ('y_pose', '0.00', 'Start y in the world, m'),
    ('z_pose', '0.01', 'Start z (unused: the robot stands on the floor)'),
    ('roll', '0.00', 'Start roll (unused)'),
    ('pitch', '0.00', 'Start pitch (unused)'),
    ('yaw', '0.00', 'Start heading in the world, rad'),
    ('log_level', 'info', 'log level'),
)


def generate_launch_description():
    bringup_dir = get_package_share_directory('nav2_bringup')
    launch_dir = os.path.join(bringup_dir, 'launch')
    c = {name: LaunchConfiguration(name) for name, _, _ in ARGUMENTS}
    for name in ('map', 'params_file', 'rviz_config_file'):
        c[name] = LaunchConfiguration(name)
    declared = [DeclareLaunchArgument(name, default_value=default, description=text)
                for name, default, text in ARGUMENTS]
    declared += [
        DeclareLaunchArgument(
            'map', default_value=PathJoinSubstitution(
                [FindPackageShare('mujoco_sim'), 'maps', 'warehouse.yaml']),
            description='Full path to map file to load'),
        DeclareLaunchArgument(
            'params_file', default_value=os.path.join(bringup_dir, 'params',
                                                      'nav2_params.yaml'),
            description='Full path to the ROS2 parameters file to use for all launched nodes'),
        DeclareLaunchArgument(
            'rviz_config_file', default_value=os.path.join(bringup_dir, 'rviz',
                                                           'nav2_default_view.rviz'),
            description='Full path to the RVIZ config file to use'),
    ]
    simulator = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory('diffbot_bringup'), 'launch',
            'diffbot_sim.launch.py')),
        condition=IfCondition(c['use_simulator']),
        launch_arguments={'world': c['world'], 'rviz': 'false', 'x': c['x_pose'],
                          'y': c['y_pose'], 'yaw': c['yaw']}.items())
    rviz = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(launch_dir, 'rviz_launch.py')),
        condition=IfCondition(c['use_rviz']),
        launch_arguments={'namespace': c['namespace'], 'use_namespace': c['use_namespace'],
                          'use_sim_time': c['use_sim_time'],
                          'rviz_config': c['rviz_config_file']}.items())
    bringup = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(launch_dir, 'bringup_launch.py')),
        launch_arguments={name: c[name] for name in (
            'namespace', 'use_namespace', 'slam', 'map', 'use_sim_time', 'params_file',
            'autostart', 'use_composition', 'use_respawn', 'log_level')}.items())
    return LaunchDescription([*declared, simulator, rviz, bringup])
