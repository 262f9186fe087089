# turtlesim's multisim launch file, as upstream ships it (the Jazzy "Launching nodes"
# tutorial runs it): two turtlesims, in the namespaces turtlesim1 and turtlesim2.

from launch import LaunchDescription
import launch_ros.actions


def generate_launch_description():
    return LaunchDescription([
        launch_ros.actions.Node(
            namespace='turtlesim1', package='turtlesim',
            executable='turtlesim_node', output='screen'),
        launch_ros.actions.Node(
            namespace='turtlesim2', package='turtlesim',
            executable='turtlesim_node', output='screen'),
    ])
