"""The `ros2 interface` verbs, one module each (HELP, add_arguments, main and, when the
daemon may run it, runs_in_daemon)."""
