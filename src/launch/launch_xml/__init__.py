"""launch_xml: upstream's module path for XML launch files (parsed by launch.frontend)."""
