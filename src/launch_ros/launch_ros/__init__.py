"""launch_ros: ROS 2 actions and substitutions for launch (upstream's module paths)."""

import os

from launch._missing import module_getattr

from launch_ros import (  # noqa: F401
    actions,
    event_handlers,
    events,
    parameter_descriptions,
    substitutions,
)

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
