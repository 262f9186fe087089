"""launch_ros.events: ROS events and their matchers."""

from launch_ros.events.matchers import matches_node_name

__all__ = ['matches_node_name']
