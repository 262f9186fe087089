"""Descriptions of ROS parameters for Node(parameters=[...]): a value, a named one, a file.

    ParameterValue(Command(['xacro ', path]), value_type=str)   # text, not read as YAML
    Parameter('rate', LaunchConfiguration('rate'), value_type=float)
    ParameterFile(path, allow_substs=True)                     # $(...) inside the file

Each is evaluated once a launch context is there; afterwards `value` / `name` / `param_file`
give the evaluated result, as upstream's.
"""

from __future__ import annotations

import os
from pathlib import Path
from tempfile import NamedTemporaryFile
from typing import TYPE_CHECKING, Any

import yaml
from launch.frontend.parse_substitution import parse_substitution
from launch.some_substitutions_type import SomeSubstitutionsType_types_tuple
from launch.substitutions import SubstitutionFailure
from launch.utilities import (
    ensure_argument_type,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from launch.utilities.type_utils import normalize_typed_substitution, perform_typed_substitution

if TYPE_CHECKING:
    from launch.some_substitutions_type import SomeSubstitutionsType
    from launch.utilities.type_utils import AllowedTypesType, SomeValueType
    from launch.utilities.typing_file_path import FilePath


class ParameterValue:
    """A parameter value: a scalar, substitutions, or a list of them, with an optional type."""

    def __init__(self, value: SomeValueType, *,
                 value_type: AllowedTypesType | None = None) -> None:
        self.__value = normalize_typed_substitution(value, value_type)
        self.__value_type = value_type
        self.__evaluated: Any = None

    @property
    def value(self) -> Any:
        return self.__value if self.__evaluated is None else self.__evaluated

    @property
    def value_type(self) -> Any:
        return self.__value_type

    def __str__(self) -> str:
        return (f'launch_ros.description.ParameterValue(value={self.value}, '
                f'value_type={self.value_type})')

    def evaluate(self, context: Any) -> Any:
        self.__evaluated = perform_typed_substitution(context, self.value, self.value_type)
        return self.__evaluated


class Parameter:
    """A named parameter, given to a node as `-p name:=value`."""

    def __init__(self, name: SomeSubstitutionsType, value: SomeValueType, *,
                 value_type: AllowedTypesType | None = None) -> None:
        ensure_argument_type(name, SomeSubstitutionsType_types_tuple, 'name', 'Parameter')
        self.__name = normalize_to_list_of_substitutions(name)
        self.__value = ParameterValue(value, value_type=value_type)
        self.__evaluated: tuple[str, Any] | None = None

    @property
    def name(self) -> Any:
        return self.__name if self.__evaluated is None else self.__evaluated[0]

    @property
    def value(self) -> Any:
        return self.__value.value

    @property
    def value_type(self) -> Any:
        return self.__value.value_type

    def __str__(self) -> str:
        return (f'launch_ros.description.Parameter(name={self.name}, value={self.value}, '
                f'value_type={self.value_type})')

    def evaluate(self, context: Any) -> tuple[str, Any]:
        if self.__evaluated is None:
            self.__evaluated = (perform_substitutions(context, self.__name),
                                self.__value.evaluate(context))
        return self.__evaluated


class ParameterFile:
    """A parameters file; with allow_substs its `$(...)` are performed into a temporary copy
    (deleted by `cleanup()`)."""

    def __init__(self, param_file: FilePath | SomeSubstitutionsType, *,
                 allow_substs: bool | SomeSubstitutionsType = False) -> None:
        self.__evaluated: Path | None = None
        self.__temporary = False  # set before any check: __del__ runs even if __init__ raises
        ensure_argument_type(param_file, (*SomeSubstitutionsType_types_tuple, os.PathLike,
                                          bytes), 'param_file', 'ParameterFile()')
        ensure_argument_type(allow_substs, (bool, *SomeSubstitutionsType_types_tuple),
                             'allow_substs', 'ParameterFile()')
        # A path stays a path; text and substitutions are performed when evaluated.
        self.__param_file = (param_file if isinstance(param_file, (os.PathLike, bytes))
                             else normalize_to_list_of_substitutions(param_file))
        self.__allow_substs = normalize_typed_substitution(allow_substs, bool)
        self.__evaluated_allow_substs: bool | None = None

    @property
    def param_file(self) -> Any:
        return self.__param_file if self.__evaluated is None else self.__evaluated

    @property
    def allow_substs(self) -> Any:
        if self.__evaluated_allow_substs is None:
            return self.__allow_substs
        return self.__evaluated_allow_substs

    def __str__(self) -> str:
        return (f'launch_ros.description.ParameterFile(param_file={self.param_file}, '
                f'allow_substs={self.allow_substs})')

    def evaluate(self, context: Any) -> Path:
        if self.__evaluated is not None:
            return self.__evaluated
        path = self.__param_file
        if isinstance(path, list):
            path = perform_substitutions(context, path)
        path = Path(os.fsdecode(path))
        self.__evaluated_allow_substs = perform_typed_substitution(
            context, self.__allow_substs, bool)
        if self.__evaluated_allow_substs:
            text = perform_substitutions(context, parse_substitution(path.read_text()))
            try:
                yaml.safe_load(text)
            except yaml.YAMLError:
                raise SubstitutionFailure(
                    'The substituted parameter file is not a valid yaml file') from None
            with NamedTemporaryFile('w', prefix='launch_params_', delete=False) as handle:
                handle.write(text)
            path = Path(handle.name)
            self.__temporary = True
        self.__evaluated = path
        return path

    def cleanup(self) -> None:
        """Delete the substituted copy, if one was made."""
        if self.__temporary and self.__evaluated is not None:
            self.__evaluated.unlink(missing_ok=True)
            self.__evaluated = None
            self.__temporary = False

    def __del__(self) -> None:
        self.cleanup()


__all__ = ['Parameter', 'ParameterFile', 'ParameterValue']
