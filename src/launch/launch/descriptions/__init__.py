"""launch.descriptions: what a process action runs (Executable)."""

from launch.descriptions.executable import Executable

__all__ = ['Executable']
