"""The talker and a best-effort listener."""
from launch_ros.actions import Node

from launch import LaunchDescription


def generate_launch_description() -> LaunchDescription:
    first = Node(package='demo_nodes_cpp', executable='talker', output='screen')
    second = Node(package='demo_nodes_cpp', executable='listener_best_effort', output='screen')
    return LaunchDescription([first, second])
