"""normalize_parameters: Node's `parameters` list in one form, ready for evaluate_parameters.

Files (paths, text or substitutions) become ParameterFile; dicts are flattened ('a': {'b': 1}
is 'a.b') with names as tuples of substitutions and values as:
  - int, float, bool, bytes: kept;
  - str: its YAML text (so 'True' stays the string 'True');
  - substitutions: a tuple of them (evaluated as YAML);
  - a list: all ints, all floats (ints and floats: floats), all bools, all text (each item
    its own string), or text and substitutions forming one string.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import yaml
from launch.some_substitutions_type import SomeSubstitutionsType_types_tuple
from launch.substitution import Substitution
from launch.substitutions import TextSubstitution
from launch.utilities import ensure_argument_type, normalize_to_list_of_substitutions

from launch_ros.parameter_descriptions import Parameter, ParameterFile, ParameterValue


def _normalize_list(value: Sequence[Any]) -> tuple[Any, ...]:
    kinds = set()
    for item in value:
        ensure_argument_type(item, (float, int, str, bool, *SomeSubstitutionsType_types_tuple),
                             'subvalue')
        if isinstance(item, Substitution):
            kinds.add(Substitution)
        elif isinstance(item, (str, bool, int, float)):
            kinds.add(type(item))
        elif all(isinstance(part, (str, Substitution)) for part in item):
            kinds.add(tuple)  # text and substitutions: one string item
        else:
            raise TypeError(f'Nested lists are not supported in parameter values: {value!r}')
    if kinds == {int}:
        return tuple(int(x) for x in value)
    if kinds in ({float}, {int, float}):
        return tuple(float(x) for x in value)
    if kinds == {bool}:
        return tuple(value)
    if Substitution in kinds and kinds <= {str, Substitution}:
        return tuple(normalize_to_list_of_substitutions(value))
    # Anything else is a list of strings, each item its own list of substitutions.
    return tuple(normalize_to_list_of_substitutions(
        yaml.dump(item) if isinstance(item, (float, int, bool, str)) else item)
        for item in value)


def normalize_parameter_dict(parameters: Mapping[Any, Any], *,
                             _prefix: list[Any] | None = None) -> dict[tuple[Any, ...], Any]:
    if not isinstance(parameters, Mapping):
        raise TypeError('expected dict')
    normalized: dict[tuple[Any, ...], Any] = {}
    for name, value in parameters.items():
        ensure_argument_type(name, (*SomeSubstitutionsType_types_tuple, tuple, list),
                             'parameter name')
        name = normalize_to_list_of_substitutions(name)
        if _prefix:
            name = [*_prefix, TextSubstitution(text='.'), *name]
        if isinstance(value, Mapping):
            normalized.update(normalize_parameter_dict(value, _prefix=name))
        elif isinstance(value, ParameterValue):
            normalized[tuple(name)] = value
        elif isinstance(value, str):
            normalized[tuple(name)] = tuple(normalize_to_list_of_substitutions(yaml.dump(value)))
        elif isinstance(value, Substitution):
            normalized[tuple(name)] = (value,)
        elif isinstance(value, (float, bool, int, bytes)):
            normalized[tuple(name)] = value
        elif isinstance(value, Sequence):
            normalized[tuple(name)] = _normalize_list(value)
        else:
            raise TypeError(f'Unexpected type for parameter value {value!r}')
    return normalized


def normalize_parameters(parameters: Any) -> tuple[Any, ...]:
    if isinstance(parameters, str) or not isinstance(parameters, Sequence):
        raise TypeError(f'Expecting list of parameters, got {parameters}')
    normalized: list[Any] = []
    for item in parameters:
        if isinstance(item, Mapping):
            normalized.append(normalize_parameter_dict(item))
        elif isinstance(item, (Parameter, ParameterFile)):
            normalized.append(item)
        else:
            normalized.append(ParameterFile(item))
    return tuple(normalized)
