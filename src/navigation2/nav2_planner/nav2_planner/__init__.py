"""Nav2 planner_server in Python."""
