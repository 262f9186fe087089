"""ros2node's API: what the `ros2 node` verbs share."""
