"""Nav2's NavFn global planner in Python."""
