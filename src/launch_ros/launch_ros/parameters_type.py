"""The parameter types of launch_ros' public API, under upstream's names.

`Node(parameters=...)`, `ComposableNode(parameters=...)` and `SetParameter(value=...)` are
annotated with these; the `*_types_tuple` is what isinstance checks accept at run time.
"""

import pathlib
from collections.abc import Mapping, Sequence
from typing import Any

from launch.some_substitutions_type import (
    SomeSubstitutionsType,
    SomeSubstitutionsType_types_tuple,
)
from launch.substitution import Substitution

from launch_ros.parameter_descriptions import Parameter as ParameterDescription
from launch_ros.parameter_descriptions import ParameterFile
from launch_ros.parameter_descriptions import ParameterValue as ParameterValueDescription

# One value, or a uniform list of them, as a ROS parameter holds it.
_SingleValueType = str | int | float | bool
_SingleValueType_types_tuple = (str, int, float, bool)
_MultiValueType = Sequence[str] | Sequence[int] | Sequence[float] | Sequence[bool] | bytes

# What a user may write.
SomeParameterFile = SomeSubstitutionsType | pathlib.Path | ParameterFile
SomeParameterName = Sequence[Substitution | str]
SomeParameterValue = (ParameterValueDescription | SomeSubstitutionsType
                      | Sequence[SomeSubstitutionsType] | _SingleValueType | _MultiValueType)
SomeParameterValue_types_tuple = (
    *SomeSubstitutionsType_types_tuple, *_SingleValueType_types_tuple, bytes)
# Nested dicts ({'ns': {'param': 1}}) are allowed; their inner level is left as Any because a
# recursive alias would not be understood by every checker.
_SomeParametersDict = Mapping[SomeParameterName, Any]
SomeParametersDict = Mapping[SomeParameterName, SomeParameterValue | _SomeParametersDict]
# Parameter files, dicts of parameters, or Parameter descriptions.
SomeParameters = Sequence[SomeParameterFile | ParameterDescription | SomeParametersDict]

# What normalize_parameters() makes of them (flat dicts of substitution lists).
ParameterName = Sequence[Substitution]
ParameterValue = (Sequence[Substitution] | Sequence[Sequence[Substitution]] | _SingleValueType
                  | _MultiValueType | ParameterValueDescription)
ParametersDict = dict[ParameterName, ParameterValue]
Parameters = Sequence[ParameterFile | ParametersDict | ParameterDescription]

# What evaluate_parameters() makes of those once substitutions are performed.
EvaluatedParameterValue = _SingleValueType | _MultiValueType
EvaluatedParameters = Sequence[
    pathlib.Path | ParameterDescription | dict[str, EvaluatedParameterValue]]

__all__ = [
    'EvaluatedParameterValue', 'EvaluatedParameters', 'ParameterFile', 'ParameterName',
    'ParameterValue', 'Parameters', 'ParametersDict', 'SomeParameterFile', 'SomeParameterName',
    'SomeParameterValue', 'SomeParameterValue_types_tuple', 'SomeParameters',
    'SomeParametersDict',
]
