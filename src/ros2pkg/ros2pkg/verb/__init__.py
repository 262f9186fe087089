"""The `ros2 pkg` verbs, one module each (HELP, add_arguments, main)."""
