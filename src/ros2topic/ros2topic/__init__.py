"""Upstream's `ros2topic` module name: `ros2topic.api`, which tools written against ros2cli
import. The `ros2 topic` verbs themselves are ros2cli_lite's (ros2cli_lite/command/topic)."""
