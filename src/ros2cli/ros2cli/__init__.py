"""Upstream ros2cli's importable modules for third-party command line tools.

The `ros2` command is ros2cli_lite's; what tools written against ros2cli import by name
(`ros2cli.node.strategy.NodeStrategy`, `add_arguments`, ...) is here, on top of it.
"""
