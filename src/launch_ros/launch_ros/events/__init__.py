"""launch_ros.events: the ROS events of launch (lifecycle)."""

from launch_ros.events import lifecycle  # noqa: F401
