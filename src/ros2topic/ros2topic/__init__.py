"""ros2topic: the `ros2 topic` command (command/topic.py, one module per verb under verb/)
and its API (api/: what the verbs share, and upstream's ros2topic.api names)."""
