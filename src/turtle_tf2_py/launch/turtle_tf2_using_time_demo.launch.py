"""The "Using time" page (C++ only upstream) in Python: the demo, looking up at time "now".

    ros2 launch turtle_tf2_py turtle_tf2_using_time_demo.launch.py timeout:=0.0
        (the page's first step: "Lookup would require extrapolation into the future")
    ros2 launch turtle_tf2_py turtle_tf2_using_time_demo.launch.py
        (the page's fix: wait up to 50 ms for the transform)
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration

from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument(
            'target_frame', default_value='turtle1',
            description='Target frame name.'
        ),
        DeclareLaunchArgument(
            'timeout', default_value='0.05',
            description='Seconds lookup_transform waits for the transform at "now".'
        ),
        Node(
            package='turtlesim',
            executable='turtlesim_node',
            name='sim'
        ),
        Node(
            package='turtle_tf2_py',
            executable='turtle_tf2_broadcaster',
            name='broadcaster1',
            parameters=[
                {'turtlename': 'turtle1'}
            ]
        ),
        Node(
            package='turtle_tf2_py',
            executable='turtle_tf2_broadcaster',
            name='broadcaster2',
            parameters=[
                {'turtlename': 'turtle2'}
            ]
        ),
        Node(
            package='turtle_tf2_py',
            executable='turtle_tf2_listener_using_time',
            name='listener',
            parameters=[
                {'target_frame': LaunchConfiguration('target_frame'),
                 'timeout': LaunchConfiguration('timeout')}
            ]
        ),
    ])
