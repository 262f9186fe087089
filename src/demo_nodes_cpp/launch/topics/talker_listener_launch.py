"""A talker and a listener on /chatter."""
from launch_ros.actions import Node

from launch import LaunchDescription


def generate_launch_description() -> LaunchDescription:
    first = Node(package='demo_nodes_cpp', executable='talker', output='screen')
    second = Node(package='demo_nodes_cpp', executable='listener', output='screen')
    return LaunchDescription([first, second])
