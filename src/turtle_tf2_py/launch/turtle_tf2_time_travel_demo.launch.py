"""The "Traveling in time" page (C++ only upstream) in Python: turtle2 follows where carrot1
was 5 seconds ago.

    ros2 launch turtle_tf2_py turtle_tf2_time_travel_demo.launch.py fixed_frame:=''
        (the page's first step: turtle2 drives around uncontrollably)
    ros2 launch turtle_tf2_py turtle_tf2_time_travel_demo.launch.py
        (the page's fix: lookup_transform_full through the fixed frame `world`)
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration

from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument(
            'target_frame', default_value='carrot1',
            description='Target frame name.'
        ),
        DeclareLaunchArgument(
            'delay', default_value='5.0',
            description='How many seconds back turtle2 looks at the target frame.'
        ),
        DeclareLaunchArgument(
            'fixed_frame', default_value='world',
            description="Frame that does not move; '' for the page's first (wrong) lookup."
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
            executable='fixed_frame_tf2_broadcaster',
            name='fixed_broadcaster',
        ),
        Node(
            package='turtle_tf2_py',
            executable='turtle_tf2_listener_time_travel',
            name='listener',
            parameters=[
                {'target_frame': LaunchConfiguration('target_frame'),
                 'delay': LaunchConfiguration('delay'),
                 'fixed_frame': LaunchConfiguration('fixed_frame')}
            ]
        ),
    ])
