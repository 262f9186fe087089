"""launch_ros: ROS 2 actions and substitutions for launch (upstream's module paths)."""

import os

from launch._missing import module_getattr

from launch_ros import actions, parameter_descriptions, substitutions  # noqa: F401

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
