"""`ros2 launch nav2_map_server map_saver_server.launch.py`: map_saver_server (node map_saver)
with Nav2's default thresholds and timeout, brought up by a lifecycle_manager (autostart, sim
time), as upstream's launch file of the same name does."""

from launch import LaunchDescription
from launch_ros.actions import Node

MANAGED_NODES = ['map_saver']


def generate_launch_description() -> LaunchDescription:
    map_saver = Node(
        package='nav2_map_server', executable='map_saver_server', output='screen',
        emulate_tty=True,
        parameters=[{'save_map_timeout': 2.0, 'free_thresh_default': 0.25,
                     'occupied_thresh_default': 0.65}])
    lifecycle_manager = Node(
        package='nav2_lifecycle_manager', executable='lifecycle_manager',
        name='lifecycle_manager', output='screen', emulate_tty=True,
        parameters=[{'use_sim_time': True, 'autostart': True, 'node_names': MANAGED_NODES}])
    return LaunchDescription([map_saver, lifecycle_manager])
