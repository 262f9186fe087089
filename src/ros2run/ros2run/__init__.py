"""ros2run: the `ros2 run` command (command/run.py) and its API (api/)."""
