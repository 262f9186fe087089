"""launch_yaml: upstream's module path for YAML launch files (parsed by launch.frontend)."""
