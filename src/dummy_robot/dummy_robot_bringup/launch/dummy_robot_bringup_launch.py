"""`ros2 launch dummy_robot_bringup dummy_robot_bringup_launch.py`: the dummy robot, its
map, laser and joint states, and robot_state_publisher turning them into TF."""

from pathlib import Path

from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

from launch import LaunchDescription


def generate_launch_description() -> LaunchDescription:
    share = FindPackageShare('dummy_robot_bringup').find('dummy_robot_bringup')
    urdf = (Path(share) / 'launch' / 'single_rrbot.urdf').read_text()
    return LaunchDescription([
        Node(package='dummy_map_server', executable='dummy_map_server', output='screen'),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             output='screen', parameters=[{'robot_description': urdf}]),
        Node(package='dummy_sensors', executable='dummy_joint_states', output='screen'),
        Node(package='dummy_sensors', executable='dummy_laser', output='screen'),
    ])
