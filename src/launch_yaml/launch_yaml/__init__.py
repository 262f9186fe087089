"""launch_yaml: the YAML front end of launch (`launch: [- node: {pkg: ..., exec: ...}]`)."""

from launch_yaml.parser import Parser

__all__ = ['Parser']
