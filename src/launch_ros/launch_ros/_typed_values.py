"""Typed substitutions (ParameterValue's value_type), for a launch without
`launch.utilities.type_utils`: upstream's rules in brief. `_launch_api` prefers launch's own.

A value is a scalar (int, float, bool, str), substitutions (one string, read as YAML unless
the type is str), or a list mixing scalars and substitutions. A data type is int, float,
bool, str, List[int], List[float], List[bool], List[str], or None (YAML's reading, which must
give one of those).
"""

from __future__ import annotations

import typing
from collections.abc import Iterable
from typing import Any

import yaml
from launch.substitution import Substitution

SCALARS = (int, float, bool, str)


def _split(data_type: Any) -> tuple[Any, bool]:
    """(scalar type or None, is a list) of a data type."""
    if data_type is None:
        return None, False
    if typing.get_origin(data_type) is list:
        (inner,) = typing.get_args(data_type)
        data_type, is_list = inner, True
    else:
        is_list = False
    if data_type not in SCALARS:
        raise ValueError(f'Unrecognized data type: {data_type}')
    return data_type, is_list


def _is_substitution(value: Any) -> bool:
    if isinstance(value, Substitution):
        return True
    if isinstance(value, str) or not isinstance(value, Iterable):
        return False
    items = list(value)
    return bool(items) and all(isinstance(x, (Substitution, str)) for x in items) and any(
        isinstance(x, Substitution) for x in items)


def _uniform(value: list[Any], scalar: Any = None) -> bool:
    """Every item of one allowed type (ints count as floats in a float list)."""
    if scalar is not None:
        return all(isinstance(x, scalar) and not (scalar is int and isinstance(x, bool))
                   for x in value)
    kinds = {type(x) for x in value}
    return len(kinds) <= 1 and kinds <= set(SCALARS)


def normalize_typed_substitution(value: Any, data_type: Any) -> Any:
    from launch_ros._launch_api import normalize_to_list_of_substitutions
    scalar, is_list = _split(data_type)
    if isinstance(value, SCALARS):
        if data_type is not None and (is_list or not isinstance(value, scalar)):
            raise TypeError(f"value='{value}' is not an instance of {data_type}")
        return value
    if _is_substitution(value):
        return normalize_to_list_of_substitutions(value)
    if not isinstance(value, Iterable):
        raise TypeError('value should be either a scalar, a substitutions, or a mixed list of '
                        f'scalars and substitutions. Got `value={value}` of type '
                        f'`{type(value)}`.')
    if data_type is not None and not is_list:
        raise TypeError('The provided value resolves to a list, though the required type is a '
                        f"scalar. Got value='{value}', data_type='{data_type}'.")
    items: list[Any] = []
    for item in value:
        if isinstance(item, SCALARS):
            items.append(item)
        elif _is_substitution(item):
            items.append(normalize_to_list_of_substitutions(item))
        else:
            raise TypeError('value is a list, and one of the items is not a scalar, a '
                            f"Substitution or a list of substitutions. Got value='{value}'")
    plain = [x for x in items if not isinstance(x, list)]
    if {type(x) for x in plain} <= {int, float} and any(isinstance(x, float) for x in plain):
        items = [x if isinstance(x, list) else float(x) for x in items]
        plain = [float(x) for x in plain]
    if not _uniform(plain, scalar):
        raise TypeError(f"Got a list of mixed types, expected a list of '{scalar}'. "
                        f"value='{value}'")
    return items


def _coerce(text: str, scalar: Any, is_list: bool) -> Any:
    if scalar is str and not is_list:
        return text
    if scalar in (int, float) and not is_list:
        return scalar(text)
    if scalar is bool and text in ('0', '1'):
        text = 'false' if text == '0' else 'true'
    if not text:
        return text
    try:
        output = yaml.safe_load(text)
    except yaml.YAMLError as error:
        raise ValueError(f"Failed to convert '{text}' using yaml rules: {error}") from None
    if is_list:
        if not isinstance(output, list) or not _uniform(output, scalar):
            raise ValueError(f"Cannot convert value '{text}' to a list of '{scalar}'")
    elif scalar is not None:
        if not isinstance(output, scalar):
            raise ValueError(f"Cannot convert value '{text}' to '{scalar}'")
    elif not (isinstance(output, SCALARS) or (isinstance(output, list) and _uniform(output))):
        raise ValueError(f"Failed to convert '{text}' using yaml rules: output type is not "
                         f'allowed, got {type(output)}')
    return output


def _is_normalized(value: Any) -> bool:
    return isinstance(value, list) and bool(value) and all(
        isinstance(x, Substitution) for x in value)


def perform_typed_substitution(context: Any, value: Any, data_type: Any) -> Any:
    from launch_ros._launch_api import perform_substitutions
    scalar, is_list = _split(data_type)
    if isinstance(value, SCALARS):
        if data_type is not None and (is_list or not isinstance(value, scalar)):
            raise TypeError(f'value=`{value}` is a scalar and not an instance of `{data_type}`')
        return value
    if _is_normalized(value):
        return _coerce(perform_substitutions(context, value), scalar, is_list)
    if isinstance(value, list):
        if data_type is not None and not is_list:
            raise ValueError('The input value is a list, cannot convert it to a scalar. '
                             f"Got value='{value}', expected type {scalar}.")
        output = [_coerce(perform_substitutions(context, x), scalar, False)
                  if _is_normalized(x) else x for x in value]
        if not _uniform(output, scalar):
            raise ValueError('The output list is not uniform' if scalar is None else
                             f"The output list does not match the expected type {scalar}")
        return output
    raise TypeError(f"Input value is not an acceptable value: '{value}'")
