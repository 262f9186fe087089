"""launch.launch_description_sources: where a launch description comes from (a file, ...)."""

from __future__ import annotations

import importlib.util
import os
from typing import TYPE_CHECKING

from launch._missing import module_getattr
from launch.substitution import (
    SomeSubstitutionsType,
    describe,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.launch_description import LaunchDescription


class InvalidLaunchFileError(Exception):
    def __init__(self, extension: str, error: BaseException) -> None:
        detail = f'{error}'
        if isinstance(error, SyntaxError):
            detail = f'{error.msg} ({os.path.basename(error.filename or "")}, line {error.lineno})'
        elif isinstance(error, ModuleNotFoundError) and (error.name or '').startswith('launch'):
            detail += ', which this launch does not provide (see docs/launch.md)'
        super().__init__(f'Caught exception when trying to load file of format [{extension}]: '
                         f'{detail}')


class LaunchDescriptionSource:
    """A launch description given directly (or loaded by a subclass from `location`)."""

    def __init__(self, launch_description: LaunchDescription | None = None,
                 location: str = '<string>', method: str = 'unspecified mechanism') -> None:
        self._launch_description = launch_description
        self._location = location
        self.method = method

    @property
    def location(self) -> str:
        return self._location

    def get_launch_description(self, context: LaunchContext) -> LaunchDescription:
        if self._launch_description is None:
            raise RuntimeError('LaunchDescriptionSource has no launch description')
        return self._launch_description


class _FileSource(LaunchDescriptionSource):
    """A launch description loaded from a file path (substitutions allowed)."""

    file_format: str | None = None  # 'py', 'xml', 'yaml'; None: told by the file's name

    def __init__(self, launch_file_path: SomeSubstitutionsType, method: str) -> None:
        super().__init__(None, '<not yet performed>', method)
        self._path = normalize_to_list_of_substitutions(launch_file_path)

    @property
    def location(self) -> str:
        return self._location if self._launch_description is not None else describe(self._path)

    def get_launch_description(self, context: LaunchContext) -> LaunchDescription:
        if self._launch_description is None:
            path = perform_substitutions(context, self._path)
            self._location = path
            self._launch_description = load_launch_file(path, self.file_format)
        return self._launch_description


class PythonLaunchDescriptionSource(_FileSource):
    file_format = 'py'

    def __init__(self, launch_file_path: SomeSubstitutionsType) -> None:
        super().__init__(launch_file_path, 'interpreted python launch file')


class FrontendLaunchDescriptionSource(_FileSource):
    """An XML or YAML file (launch_xml's and launch_yaml's sources fix the format)."""

    def __init__(self, launch_file_path: SomeSubstitutionsType, *,
                 method: str = 'interpreted frontend launch file') -> None:
        super().__init__(launch_file_path, method)


class AnyLaunchDescriptionSource(_FileSource):
    """A Python, XML or YAML launch file, told apart by its name."""

    def __init__(self, launch_file_path: SomeSubstitutionsType) -> None:
        super().__init__(launch_file_path, 'interpreted launch file')


def file_kind(path: str) -> str:
    if path.endswith('.py'):
        return 'py'
    if path.endswith('.xml'):
        return 'xml'
    if path.endswith(('.yaml', '.yml')):
        return 'yaml'
    return 'py'


def load_launch_file(path: str, kind: str | None = None) -> LaunchDescription:
    """The LaunchDescription of a launch file; one-line errors (InvalidLaunchFileError)."""
    kind = kind or file_kind(path)
    if not os.path.isfile(path):
        raise InvalidLaunchFileError(kind, FileNotFoundError(f"launch file '{path}' not found"))
    try:
        if kind == 'py':
            return _load_python(path)
        from launch.frontend.parser import load_frontend_file
        return load_frontend_file(path, kind)
    except InvalidLaunchFileError:
        raise
    except Exception as error:
        raise InvalidLaunchFileError(kind, error) from error


def _load_python(path: str) -> LaunchDescription:
    from launch.launch_description import LaunchDescription
    spec = importlib.util.spec_from_file_location('python_launch_file', path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    generate = getattr(module, 'generate_launch_description', None)
    if generate is None:
        raise RuntimeError(f"launch file at '{path}' does not contain the required function "
                           "'generate_launch_description()'")
    description = generate()
    if not isinstance(description, LaunchDescription):
        raise RuntimeError(f"generate_launch_description() of '{path}' returned "
                           f'{type(description).__name__}, not a LaunchDescription')
    return description


def get_launch_description_from_any_launch_file(path: str) -> LaunchDescription:
    return load_launch_file(path)


def get_launch_description_from_python_launch_file(path: str) -> LaunchDescription:
    return load_launch_file(path, 'py')


__all__ = ['AnyLaunchDescriptionSource', 'FrontendLaunchDescriptionSource',
           'InvalidLaunchFileError', 'LaunchDescriptionSource', 'PythonLaunchDescriptionSource',
           'get_launch_description_from_any_launch_file',
           'get_launch_description_from_python_launch_file', 'load_launch_file']

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
