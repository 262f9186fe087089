"""The turtle demo: turtlesim and turtle_controller, stopped together.

    ros2 launch my_robot_controller turtle_demo.launch.py
    ros2 launch my_robot_controller turtle_demo.launch.py seconds:=20 headless:=true \
        canvas_png:=/tmp/canvas.png controller_args:='--ros-args -p boundary_x:=4.0'

When either node exits, or `seconds` run out, the launch shuts down: both nodes get Ctrl-C
(SIGINT) and turtlesim writes its canvas PNG as it exits.
"""

import os
import shlex
import tempfile

from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, LogInfo, OpaqueFunction,
                            RegisterEventHandler, Shutdown, TimerAction)
from launch.conditions import IfCondition
from launch.event_handlers import OnProcessExit
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def _on_node_exit(event, context):
    """Whichever node exits first stops the other; turtlesim's exit means a final canvas."""
    actions = []
    if not context.is_shutdown:
        name = event.action.node_executable
        reason = f'{name} exited with code {event.returncode}'
        actions += [LogInfo(msg=f'stopping ({reason})'), Shutdown(reason=reason)]
    if event.action.node_executable == 'turtlesim_node':
        canvas = LaunchConfiguration('canvas_png').perform(context)
        if os.path.isfile(canvas):
            actions.append(LogInfo(msg=f'final canvas saved: {canvas}'))
        else:
            actions.append(LogInfo(msg=f'warning: turtlesim did not write the final canvas '
                                       f'to {canvas}'))
    return actions


def _nodes(context):
    canvas = LaunchConfiguration('canvas_png').perform(context)
    headless = LaunchConfiguration('headless').perform(context).lower() in ('true', '1')
    turtlesim = Node(package='turtlesim', executable='turtlesim_node', output='screen',
                     arguments=['--canvas-png', canvas] + (['--headless'] if headless else []))
    controller = Node(package='my_robot_controller', executable='turtle_controller',
                      output='screen',
                      arguments=shlex.split(LaunchConfiguration('controller_args')
                                            .perform(context)))
    exits = [RegisterEventHandler(OnProcessExit(target_action=node, on_exit=_on_node_exit))
             for node in (turtlesim, controller)]
    return [*exits, turtlesim, controller]


def generate_launch_description():
    seconds = LaunchConfiguration('seconds')
    return LaunchDescription([
        DeclareLaunchArgument(
            'canvas_png', description='where turtlesim writes the canvas PNG',
            default_value=os.path.join(tempfile.gettempdir(), 'turtle_demo_canvas.png')),
        DeclareLaunchArgument('headless', default_value='false',
                              description='no window even when a display exists'),
        DeclareLaunchArgument('seconds', default_value='0',
                              description='stop after this many seconds (0: until Ctrl-C)'),
        DeclareLaunchArgument('controller_args', default_value='',
                              description='arguments for turtle_controller, e.g. '
                                          "'--ros-args -p boundary_x:=4.0'"),
        OpaqueFunction(function=_nodes),
        TimerAction(
            period=seconds, condition=IfCondition(PythonExpression([seconds, ' > 0'])),
            actions=[LogInfo(msg='stopping (time is up)'), Shutdown(reason='time is up')]),
    ])
