"""Typed values in launch files: which types are allowed, and turning text into them.

Scalars are int, float, bool and str; lists are List[one of those]. Text is read with YAML
rules ('1' is an int, 'true' a bool), except that a bool also takes '1' and '0'.
"""

from __future__ import annotations

import collections.abc
import typing
from typing import TYPE_CHECKING, Any

import yaml

from launch.some_substitutions_type import SomeSubstitutionsType
from launch.substitution import Substitution
from launch.utilities.ensure_argument_type_impl import ensure_argument_type
from launch.utilities.normalize_to_list_of_substitutions_impl import (
    normalize_to_list_of_substitutions,
)
from launch.utilities.perform_substitutions_impl import perform_substitutions

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext

ScalarTypesTuple = (int, float, bool, str)
# typing.List itself (not the builtin list) is what names a list type in upstream's API.
_TypingList = typing.List  # noqa: UP006
ListTypesTuple = (_TypingList[int], _TypingList[float], _TypingList[bool], _TypingList[str])
AllowedTypesTuple = ScalarTypesTuple + ListTypesTuple
# The aliases below are for annotations only (isinstance checks use the *Tuple ones above).
ScalarTypesType = type[int | float | bool | str]
ListTypesType = type[list[int] | list[float] | list[bool] | list[str]]
AllowedTypesType = ScalarTypesType | ListTypesType
ScalarValueType = int | float | bool | str
ListValueType = list[int] | list[float] | list[bool] | list[str]
SequenceValueType = (collections.abc.Sequence[int] | collections.abc.Sequence[float]
                     | collections.abc.Sequence[bool] | collections.abc.Sequence[str])
AllowedValueType = ScalarValueType | SequenceValueType
# A typed value as a user writes it: the value itself, or substitutions that yield its text.
SomeScalarType = SomeSubstitutionsType | ScalarValueType
SomeSequenceType = (collections.abc.Sequence[int | SomeSubstitutionsType]
                    | collections.abc.Sequence[float | SomeSubstitutionsType]
                    | collections.abc.Sequence[bool | SomeSubstitutionsType]
                    | collections.abc.Sequence[str | SomeSubstitutionsType])
SomeValueType = SomeScalarType | SomeSequenceType
# The same after normalize_typed_substitution(): substitutions as lists of Substitution.
NormalizedScalarType = list[Substitution] | ScalarValueType
NormalizedSequenceType = (list[int | list[Substitution]] | list[float | list[Substitution]]
                          | list[bool | list[Substitution]] | list[str | list[Substitution]])
NormalizedValueType = NormalizedScalarType | NormalizedSequenceType
# Substitutions embedded in strings ('$(var x)'), as the front ends hand them over.
StrSomeScalarType = SomeScalarType
StrSomeSequenceType = (collections.abc.Sequence[int | str] | collections.abc.Sequence[float | str]
                       | collections.abc.Sequence[bool | str] | collections.abc.Sequence[str])
StrSomeValueType = StrSomeScalarType | StrSomeSequenceType

_TYPES_ALLOWED = ('int, float, str, bool, List[int], List[float], List[str], List[bool]')


def is_typing_list(data_type: Any) -> bool:
    """True for typing.List and List[X]."""
    return data_type is _TypingList or getattr(data_type, '__origin__', None) in (
        list, _TypingList)


def is_valid_scalar_type(data_type: Any) -> bool:
    return data_type in ScalarTypesTuple


def extract_type(data_type: Any) -> tuple[type, bool]:
    """(scalar type, is it a list?) of an allowed type; ValueError for any other."""
    is_list = False
    scalar = data_type
    if is_typing_list(data_type) and getattr(data_type, '__args__', None):
        is_list = True
        scalar = data_type.__args__[0]
    if not is_valid_scalar_type(scalar):
        raise ValueError(f'Unrecognized data type: {data_type}')
    return scalar, is_list


def is_instance_of_valid_type(value: Any, *, can_be_str: bool = False) -> bool:
    """A scalar of an allowed type, or a list whose items share one (strings allowed too)."""
    if isinstance(value, list):
        if not value:
            return True
        item_type = next((type(item) for item in value if type(item) is not str), str)
        if item_type not in ScalarTypesTuple:
            return False
        allowed = (item_type, str) if can_be_str else item_type
        return all(isinstance(item, allowed) for item in value)
    return isinstance(value, ScalarTypesTuple)


def is_instance_of(value: Any, data_type: Any = None, *, can_be_str: bool = False) -> bool:
    if data_type is None:
        return is_instance_of_valid_type(value, can_be_str=can_be_str)
    scalar, is_list = extract_type(data_type)
    allowed: Any = (str, scalar) if can_be_str else scalar
    if not is_list:
        return isinstance(value, allowed)
    return isinstance(value, list) and all(isinstance(item, allowed) for item in value)


def _from_yaml(value: str, error: str, can_be_str: bool) -> Any:
    if not value:
        return value
    try:
        output = yaml.safe_load(value)
    except Exception as exc:
        if can_be_str:
            return value
        raise ValueError(f'{error}: yaml.safe_load() failed\n{exc}') from None
    if not is_instance_of_valid_type(output, can_be_str=can_be_str):
        raise ValueError(f'{error}: output type is not allowed, got {type(output)}')
    return output


def coerce_to_type(value: str, data_type: Any = None, *, can_be_str: bool = False) -> Any:
    """Text as `data_type` (YAML rules when None); ValueError when it is not one."""
    ensure_argument_type(value, str, 'value', 'coerce_to_type')
    if data_type is None:
        return _from_yaml(value, f"Failed to convert '{value}' using yaml rules", can_be_str)
    scalar, is_list = extract_type(data_type)
    allowed: Any = (str, scalar) if can_be_str else scalar
    if is_list:
        error = f"Cannot convert value '{value}' to a list of '{allowed}'"
        output = _from_yaml(value, error, can_be_str)
        if not isinstance(output, list):
            raise ValueError(error)
        if not all(isinstance(item, allowed) for item in output):
            raise ValueError(f'{error}, got {output}')
        return output
    if scalar is str:
        return value
    if scalar in (int, float):
        try:
            return scalar(value)
        except ValueError:
            if can_be_str:
                return value
            raise
    # bool: YAML's spellings, and '1' / '0' as true / false
    value = {'1': 'true', '0': 'false'}.get(value, value)
    output = _from_yaml(value, f"Failed to convert '{value}' to '{scalar}'", can_be_str)
    if isinstance(output, allowed):
        return output
    raise ValueError(f"Cannot convert value '{value}' to '{scalar}'")


def coerce_list(value: list[str], data_type: Any = None, *, can_be_str: bool = False) -> Any:
    ensure_argument_type(value, list, 'value', 'coerce_list')
    output = [coerce_to_type(item, data_type, can_be_str=can_be_str) for item in value]
    if not is_instance_of_valid_type(output, can_be_str=can_be_str):
        raise ValueError(f'cannot convert value to {data_type}. Got value=`{value}`')
    return output


def get_typed_value(value: str | list[str], data_type: Any, *,
                    can_be_str: bool = False) -> Any:
    """Text, or a list of texts, as `data_type`."""
    if not isinstance(value, list):
        return coerce_to_type(value, data_type, can_be_str=can_be_str)
    if data_type is not None:
        data_type, is_list = extract_type(data_type)
        if not is_list:
            raise TypeError(f"Cannot convert input '{value}' of type '{type(value)}' to "
                            f"'{data_type}'")
    return coerce_list(value, data_type, can_be_str=can_be_str)


def is_substitution(x: Any) -> bool:
    """A substitution, or a non-empty iterable of text and substitutions with one at least."""
    if isinstance(x, Substitution):
        return True
    if not isinstance(x, collections.abc.Iterable) or isinstance(x, str):
        return False
    items = list(x)
    return (bool(items) and all(isinstance(item, (Substitution, str)) for item in items)
            and any(isinstance(item, Substitution) for item in items))


def normalize_typed_substitution(value: Any, data_type: Any) -> Any:
    """A scalar, substitutions, or a list mixing them, checked against `data_type`."""
    if isinstance(value, ScalarTypesTuple):
        if not is_instance_of(value, data_type):
            raise TypeError(f"value='{value}' is not an instance of {data_type}")
        return value
    if is_substitution(value):
        return normalize_to_list_of_substitutions(value)
    if not isinstance(value, collections.abc.Iterable):
        raise TypeError('value should be either a scalar, a substitutions, or a mixed list of '
                        f'scalars and substitutions. Got `value={value}` of type '
                        f'`{type(value)}`. ')
    kinds: set[type] = set()
    for item in value:
        if isinstance(item, ScalarTypesTuple):
            kinds.add(type(item))
        elif is_substitution(item):
            kinds.add(Substitution)
        else:
            raise TypeError('value is a list, and one of the items is not a scalar, a '
                            f"Substitution or a list of substitutions. Got value='{value}'")
    is_list = True
    if data_type is not None:
        data_type, is_list = extract_type(data_type)
    if not is_list:
        raise TypeError('The provided value resolves to a list, though the required type is a '
                        f"scalar. Got value='{value}', data_type='{data_type}'.")

    def normalized(item: Any, convert: Any = None) -> Any:
        if is_substitution(item):
            return normalize_to_list_of_substitutions(item)
        return convert(item) if convert is not None else item

    if kinds == {Substitution}:
        return [normalize_to_list_of_substitutions(item) for item in value]
    for scalar, convert in ((str, None), (bool, None), (int, None), (float, float)):
        group = {scalar, Substitution} | ({int} if scalar is float else set())
        if kinds <= group:
            if data_type not in (None, scalar):
                raise TypeError(f"Got a list of '{scalar}', expected a list of '{data_type}'. "
                                f"value='{value}'")
            return [normalized(item, convert) for item in value]
    raise TypeError(f"Input value is not an acceptable 'SomeValueType'.Got value='{value}'")


def is_normalized_substitution(x: Any) -> bool:
    return isinstance(x, list) and bool(x) and all(isinstance(i, Substitution) for i in x)


def perform_typed_substitution(context: LaunchContext, value: Any, data_type: Any) -> Any:
    """The value of a normalized typed substitution, as `data_type`."""
    if isinstance(value, ScalarTypesTuple):
        if data_type is not None and not is_instance_of(value, data_type):
            raise TypeError(f'value=`{value}` is a scalar and not an instance of `{data_type}`')
        return value
    if is_normalized_substitution(value):
        return coerce_to_type(perform_substitutions(context, value), data_type)
    if isinstance(value, list):
        scalar: type | None = None
        if data_type is not None:
            scalar, is_list = extract_type(data_type)
            if not is_list:
                raise ValueError('The input value is a list, cannot convert it to a scalar. '
                                 f"Got value='{value}', expected type {scalar}.")
        output = [coerce_to_type(perform_substitutions(context, item), scalar)
                  if is_normalized_substitution(item) else item for item in value]
        if not is_instance_of(output, data_type):
            raise ValueError('The output list does not match the expected type '
                             f"Got value='{value}', expected type {scalar}."
                             if scalar is not None else 'The output list is not uniform')
        return output
    raise TypeError(f"Input value is not an acceptable 'NormalizedValueType'.Got value='{value}'")
