"""The introspection service and client."""
from launch_ros.actions import Node

from launch import LaunchDescription


def generate_launch_description() -> LaunchDescription:
    first = Node(package='demo_nodes_cpp', executable='introspection_service', output='screen')
    second = Node(package='demo_nodes_cpp', executable='introspection_client', output='screen')
    return LaunchDescription([first, second])
