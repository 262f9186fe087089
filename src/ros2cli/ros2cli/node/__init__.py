"""The node a command line tool talks to the graph with: the daemon's or its own."""

from ros2cli_lite.node import NODE_NAME_PREFIX

__all__ = ['NODE_NAME_PREFIX']
