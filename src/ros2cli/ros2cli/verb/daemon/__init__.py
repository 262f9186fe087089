"""The `ros2 daemon` verbs: start, stop, status (of the daemon for this shell's ROS settings)."""
