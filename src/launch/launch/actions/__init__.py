"""launch.actions: what a launch description does."""

import os

from launch._missing import module_getattr
from launch.actions.declare_launch_argument import DeclareLaunchArgument
from launch.actions.execute_process import ExecuteProcess
from launch.actions.include_launch_description import IncludeLaunchDescription
from launch.actions.simple import (
                                   AppendEnvironmentVariable,
                                   EmitEvent,
                                   GroupAction,
                                   LogInfo,
                                   OpaqueFunction,
                                   PopEnvironment,
                                   PopLaunchConfigurations,
                                   PushEnvironment,
                                   PushLaunchConfigurations,
                                   RegisterEventHandler,
                                   ResetLaunchConfigurations,
                                   SetEnvironmentVariable,
                                   SetLaunchConfiguration,
                                   Shutdown,
                                   UnregisterEventHandler,
                                   UnsetEnvironmentVariable,
                                   UnsetLaunchConfiguration,
)
from launch.actions.timer_action import TimerAction

# Upstream's ExecuteLocal is the base of ExecuteProcess; ours is one class.
ExecuteLocal = ExecuteProcess

__all__ = [
    'AppendEnvironmentVariable', 'DeclareLaunchArgument', 'EmitEvent', 'ExecuteLocal',
    'ExecuteProcess', 'GroupAction', 'IncludeLaunchDescription', 'LogInfo', 'OpaqueFunction',
    'PopEnvironment', 'PopLaunchConfigurations', 'PushEnvironment', 'PushLaunchConfigurations',
    'RegisterEventHandler', 'ResetLaunchConfigurations', 'SetEnvironmentVariable',
    'SetLaunchConfiguration', 'Shutdown', 'TimerAction', 'UnregisterEventHandler',
    'UnsetEnvironmentVariable', 'UnsetLaunchConfiguration',
]

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
