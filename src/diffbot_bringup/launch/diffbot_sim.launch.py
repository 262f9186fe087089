"""`ros2 launch diffbot_bringup diffbot_sim.launch.py [world:=room.xml] [rviz:=true|false]
[real_time_factor:=1.0] [x:=0.0] [y:=0.0] [yaw:=0.0]`: the MuJoCo world with the diffbot in
it at (x, y, yaw), robot_state_publisher on sim time (the same URDF), and the RViz page with
diffbot.rviz (robot, TF, scan, odometry and the camera image). `world` is a file of
mujoco_sim's worlds/ folder (room.xml, empty.xml, warehouse.xml) or an absolute path."""

from pathlib import Path

from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution


def generate_launch_description() -> LaunchDescription:
    description = FindPackageShare('diffbot_description').find('diffbot_description')
    urdf = (Path(description) / 'urdf' / 'diffbot.urdf').read_text()
    worlds = PathJoinSubstitution([FindPackageShare('mujoco_sim'), 'worlds',
                                   LaunchConfiguration('world')])
    rviz_config = PathJoinSubstitution([FindPackageShare('diffbot_bringup'), 'rviz',
                                        'diffbot.rviz'])
    return LaunchDescription([
        DeclareLaunchArgument('world', default_value='room.xml',
                              description="World file (MJCF) in mujoco_sim's worlds/ folder, "
                                          'or an absolute path'),
        DeclareLaunchArgument('rviz', default_value='true', choices=['true', 'false'],
                              description='Open the RViz page'),
        DeclareLaunchArgument('real_time_factor', default_value='1.0',
                              description='Sim seconds per wall second (0: as fast as possible)'),
        DeclareLaunchArgument('x', default_value='0.0', description='Start x in the world, m'),
        DeclareLaunchArgument('y', default_value='0.0', description='Start y in the world, m'),
        DeclareLaunchArgument('yaw', default_value='0.0',
                              description='Start heading in the world, rad'),
        Node(package='mujoco_sim', executable='mujoco_sim', output='screen',
             parameters=[{'robot_description': urdf, 'world': worlds,
                          'real_time_factor': LaunchConfiguration('real_time_factor'),
                          'x': LaunchConfiguration('x'), 'y': LaunchConfiguration('y'),
                          'yaw': LaunchConfiguration('yaw')}]),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             output='screen',
             parameters=[{'robot_description': urdf, 'use_sim_time': True}]),
        Node(package='rviz2', executable='rviz2', name='rviz2', output='screen',
             arguments=['-d', rviz_config], condition=IfCondition(LaunchConfiguration('rviz'))),
    ])
