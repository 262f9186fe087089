"""launch_ros: ROS 2 actions, descriptions and substitutions for launch (upstream's modules)."""

from launch_ros import (  # noqa: F401
    actions,
    descriptions,
    event_handlers,
    events,
    parameter_descriptions,
    substitutions,
    utilities,
)
