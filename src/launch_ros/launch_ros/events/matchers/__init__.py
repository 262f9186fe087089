"""launch_ros.events.matchers: which node actions an event is for."""

from launch_ros.events.matchers.matches_node_name import matches_node_name

__all__ = ['matches_node_name']
