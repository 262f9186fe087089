"""launch_ros.events.matchers: event matchers for ROS actions."""

from launch_ros.events.matchers.matches_node_name import matches_node_name

__all__ = ['matches_node_name']
