"""launch_ros: ROS 2 actions, descriptions and substitutions for launch (upstream's modules)."""

import os

from launch._missing import module_getattr

from launch_ros import (  # noqa: F401
    actions,
    descriptions,
    event_handlers,
    events,
    parameter_descriptions,
    substitutions,
    utilities,
)

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
