"""`ros2 launch lifecycle lifecycle_demo_launch.py`: lc_talker (managed), lc_listener and
lc_client, which walks lc_talker through its transitions; the launch ends with lc_client."""

from launch.actions import Shutdown
from launch_ros.actions import LifecycleNode, Node

from launch import LaunchDescription


def generate_launch_description() -> LaunchDescription:
    return LaunchDescription([
        LifecycleNode(package='lifecycle', executable='lifecycle_talker', name='lc_talker',
                      namespace='', output='screen'),
        Node(package='lifecycle', executable='lifecycle_listener', output='screen'),
        Node(package='lifecycle', executable='lifecycle_service_client', output='screen',
             on_exit=Shutdown()),
    ])
