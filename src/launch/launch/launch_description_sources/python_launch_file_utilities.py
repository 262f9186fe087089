"""Loading a Python launch file: its module, and its generate_launch_description()."""

from __future__ import annotations

from importlib.machinery import SourceFileLoader
from importlib.util import module_from_spec, spec_from_loader
from types import ModuleType
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from launch.launch_description import LaunchDescription


class InvalidPythonLaunchFileError(Exception):
    """The Python file has no generate_launch_description()."""


def load_python_launch_file_as_module(python_launch_file_path: str) -> ModuleType:
    loader = SourceFileLoader('python_launch_file', str(python_launch_file_path))
    spec = spec_from_loader(loader.name, loader)
    if spec is None:
        raise RuntimeError('Failed to load module spec!')
    module = module_from_spec(spec)
    loader.exec_module(module)
    return module


def get_launch_description_from_python_launch_file(python_launch_file_path: str
                                                   ) -> LaunchDescription:
    module = load_python_launch_file_as_module(python_launch_file_path)
    if not hasattr(module, 'generate_launch_description'):
        raise InvalidPythonLaunchFileError(
            f"launch file at '{python_launch_file_path}' does not contain the required "
            "function 'generate_launch_description()'")
    return module.generate_launch_description()
