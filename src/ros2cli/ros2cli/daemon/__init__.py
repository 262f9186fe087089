"""The `ros2` graph daemon: one long-lived rclpy node per user and ROS network settings.

`protocol` (paths, version, wire format) and `client` import no rclpy, so a graph verb that
the daemon answers starts fast; `server` is the daemon process itself. See docs/cli.md.
"""
