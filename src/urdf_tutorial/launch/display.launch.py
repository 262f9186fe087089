"""Show one of the tutorial's models: robot_state_publisher, joint_state_publisher, rviz2.

`ros2 launch urdf_tutorial display.launch.py model:=urdf/01-myfirst.urdf [gui:=true|false]
[rvizconfig:=/abs/path.rviz]`: `model` is relative to this package's share directory (or
absolute); .xacro files go through `xacro` like any URDF (Command(['xacro ', path])).
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import Command, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    package = FindPackageShare('urdf_tutorial')
    model = PathJoinSubstitution([package, LaunchConfiguration('model')])
    description = ParameterValue(Command(['xacro ', model]), value_type=str)
    return LaunchDescription([
        DeclareLaunchArgument(name='gui', default_value='true', choices=['true', 'false'],
                              description='Flag to enable joint_state_publisher_gui'),
        DeclareLaunchArgument(name='rvizconfig',
                              default_value=PathJoinSubstitution([package, 'rviz', 'urdf.rviz']),
                              description='Absolute path to rviz config file'),
        DeclareLaunchArgument(name='model',
                              default_value=PathJoinSubstitution(['urdf', '01-myfirst.urdf']),
                              description='Path to robot urdf file relative to urdf_tutorial '
                                          'package'),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': description}]),
        # The GUI's sliders are the Joint State Publisher page of the browser app.
        Node(package='joint_state_publisher_gui', executable='joint_state_publisher_gui',
             condition=IfCondition(LaunchConfiguration('gui'))),
        Node(package='joint_state_publisher', executable='joint_state_publisher',
             condition=UnlessCondition(LaunchConfiguration('gui'))),
        Node(package='rviz2', executable='rviz2', name='rviz2', output='screen',
             arguments=['-d', LaunchConfiguration('rvizconfig')]),
    ])
