"""matches_node_name, as upstream still offers it here (it lives in launch_ros.events)."""

from launch_ros.events.matchers import matches_node_name

__all__ = ['matches_node_name']
