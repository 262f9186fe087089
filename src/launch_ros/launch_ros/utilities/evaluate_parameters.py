"""evaluate_parameters: normalized parameters with their substitutions performed.

Files become paths, dicts {name: value}. A value given by substitutions is read as YAML and
must give a scalar or a non-empty list of one scalar type; wrap it in
ParameterValue(value, value_type=str) to keep it as text.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import yaml
from launch.substitution import Substitution
from launch.utilities import ensure_argument_type, perform_substitutions

from launch_ros.parameter_descriptions import Parameter, ParameterFile, ParameterValue

_AS_TEXT = ('If the parameter is meant to be a string, try wrapping it in '
            'launch_ros.parameter_descriptions.ParameterValue(value, value_type=str)')


def _uniform(values: Sequence[Any]) -> bool:
    if not values or type(values[0]) not in (bool, int, float, str):
        return False
    return all(isinstance(value, type(values[0])) for value in values)


def _not_uniform(name: str) -> TypeError:
    return TypeError('Expected a non-empty sequence, with items of uniform type. Allowed '
                     f'sequence item types are bool, int, float, str. Got inconsistent input '
                     f'for "{name}"')


def _from_yaml(name: str, text: str) -> Any:
    try:
        value = yaml.safe_load(text or "''")
    except yaml.YAMLError:
        raise TypeError(f'Unable to parse the value of parameter {name} as yaml. '
                        + _AS_TEXT) from None
    if type(value) in (bool, int, float, str, bytes):
        return value
    if isinstance(value, Sequence):
        if not _uniform(value):
            raise _not_uniform(name)
        return tuple(value)
    raise TypeError('Allowed value types are bytes, bool, int, float, str, Sequence[bool], '
                    'Sequence[int], Sequence[float], Sequence[str]. '
                    f'Got {type(value)} for "{name}". ' + _AS_TEXT)


def evaluate_parameter_dict(context: Any, parameters: Mapping[Any, Any]) -> dict[str, Any]:
    if not isinstance(parameters, Mapping):
        raise TypeError('expected dict')
    evaluated: dict[str, Any] = {}
    for name, value in parameters.items():
        if not isinstance(name, tuple):
            raise TypeError(f'Expecting tuple of substitutions got {name!r}')
        text_name = perform_substitutions(context, list(name))
        if isinstance(value, ParameterValue):
            evaluated[text_name] = value.evaluate(context)
        elif isinstance(value, tuple) and value and isinstance(value[0], Substitution):
            evaluated[text_name] = _from_yaml(text_name,
                                              perform_substitutions(context, list(value)))
        elif isinstance(value, tuple) and value and isinstance(value[0], Sequence):
            items = [yaml.safe_load(perform_substitutions(context, list(item)))
                     for item in value]
            if not _uniform(items):
                raise _not_uniform(text_name)
            evaluated[text_name] = tuple(items)
        elif isinstance(value, tuple) and value:
            evaluated[text_name] = tuple(type(value[0])(item) for item in value)
        else:
            ensure_argument_type(value, (float, int, str, bool, bytes), 'value')
            evaluated[text_name] = value
    return evaluated


def evaluate_parameters(context: Any, parameters: Sequence[Any]) -> tuple[Any, ...]:
    """Paths for files, {name: value} for dicts; Parameter descriptions are kept as they are."""
    evaluated: list[Any] = []
    for item in parameters:
        if isinstance(item, ParameterFile):
            evaluated.append(item.evaluate(context))
        elif isinstance(item, Parameter):
            evaluated.append(item)
        elif isinstance(item, Mapping):
            evaluated.append(evaluate_parameter_dict(context, item))
    return tuple(evaluated)
