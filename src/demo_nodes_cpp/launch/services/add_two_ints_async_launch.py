"""The AddTwoInts server and the asynchronous client; the launch ends when the client exits."""
from launch.actions import EmitEvent, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch.events import Shutdown
from launch_ros.actions import Node

from launch import LaunchDescription


def generate_launch_description() -> LaunchDescription:
    first = Node(package='demo_nodes_cpp', executable='add_two_ints_server', output='screen')
    second = Node(package='demo_nodes_cpp', executable='add_two_ints_client_async', output='screen')
    return LaunchDescription([first, second, RegisterEventHandler(OnProcessExit(
        target_action=second, on_exit=[EmitEvent(event=Shutdown())]))])
