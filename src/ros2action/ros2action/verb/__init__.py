"""The `ros2 action` verbs, one module each (HELP, add_arguments, main and, when the
daemon may run it, runs_in_daemon)."""
