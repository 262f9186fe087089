"""The lifecycle demo with lifecycle_py's talker: lc_talker managed by lifecycle's lc_client,
watched by lc_listener."""

from launch_ros.actions import LifecycleNode, Node

from launch import LaunchDescription


def generate_launch_description() -> LaunchDescription:
    return LaunchDescription([
        LifecycleNode(package='lifecycle_py', executable='lifecycle_talker', name='lc_talker',
                      namespace='', output='screen'),
        Node(package='lifecycle', executable='lifecycle_listener', output='screen'),
        Node(package='lifecycle', executable='lifecycle_service_client', output='screen'),
    ])
