"""launch_ros.actions: Node and the actions that scope ROS settings."""

import os

from launch._missing import module_getattr

from launch_ros.actions.lifecycle_node import LifecycleNode
from launch_ros.actions.lifecycle_transition import LifecycleTransition
from launch_ros.actions.node import Node
from launch_ros.actions.scope import (
                                      PushROSNamespace,
                                      PushRosNamespace,
                                      SetParameter,
                                      SetParametersFromFile,
                                      SetRemap,
)

__all__ = ['Node', 'PushROSNamespace', 'PushRosNamespace', 'SetParameter',
           'SetParametersFromFile', 'SetRemap']
__all__ += ['LifecycleNode', 'LifecycleTransition']

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
