"""Fill a message from plain data (YAML, a form, a dict), field by field.

Every value is checked against its field's type before it is set, and refused with one line
naming the field and what it can hold: `'linear.x' must be a number, got 'a'`. The errors keep
the exception types callers of upstream's set_message_fields catch: an unknown field is an
AttributeError, a value that is not a mapping where one is expected a TypeError, any other bad
value a ValueError; all of them are FieldError.
"""

from __future__ import annotations

import numbers
from collections.abc import Callable
from functools import partial
from typing import Any

from rosidl_parser import definition

from rosidl_runtime_py.convert import get_message_slot_types, is_numpy, is_sequence
from rosidl_runtime_py.import_message import import_message_from_namespaced_type

INTEGER_RANGES = {
    'int8': (-(2**7), 2**7 - 1), 'uint8': (0, 2**8 - 1), 'octet': (0, 2**8 - 1),
    'int16': (-(2**15), 2**15 - 1), 'uint16': (0, 2**16 - 1),
    'int32': (-(2**31), 2**31 - 1), 'uint32': (0, 2**32 - 1),
    'int64': (-(2**63), 2**63 - 1), 'uint64': (0, 2**64 - 1),
}
FLOAT32_MAX = 3.4028234663852886e38
FLOAT_TYPES = ('float', 'double', 'float32', 'float64', 'long double')


class FieldError(ValueError):
    """A value a field cannot hold; `explanation` is the one line naming field and rule."""

    def __init__(self, explanation: str) -> None:
        super().__init__(explanation)
        self.explanation = explanation


class UnknownFieldError(FieldError, AttributeError):
    """A key that is no field of the message."""


class NotAMappingError(FieldError, TypeError):
    """A message field given something other than a mapping of its fields.

    str() is upstream's text ("Value 'auto' is expected to be a dictionary but is a str"),
    which callers match; `explanation` also names the field.
    """

    def __init__(self, explanation: str, value: Any) -> None:
        super().__init__(explanation)
        self.args = (f"Value '{value}' is expected to be a dictionary but is a "
                     f'{type(value).__name__}',)


def set_message_fields(msg: Any, values: dict, expand_header_auto: bool = False,
                       expand_time_now: bool = False) -> list[Callable[[Any], None]]:
    """Set the fields of `msg` named in `values` (nested messages as nested mappings).

    With `expand_header_auto`, a std_msgs/Header given as 'auto' and with `expand_time_now` a
    builtin_interfaces/Time given as 'now' are left as they are, and a setter taking a Time
    message is returned for each: call them to stamp the message (e.g. before each publish).
    """
    stamps: list[Callable[[Any], None]] = []
    _set_fields(msg, values, '', (expand_header_auto, expand_time_now), stamps)
    return stamps


def _set_fields(msg: Any, values: Any, prefix: str, expand: tuple[bool, bool],
                stamps: list) -> None:
    if not isinstance(values, dict):
        field = prefix.rstrip('.') or _type_name(type(msg))
        raise NotAMappingError(f"'{field}' expects a mapping of field names to values, got "
                               f'{_show(values)}', values)
    slots = get_message_slot_types(msg)
    for key, value in values.items():
        path = f'{prefix}{key}'
        if key not in slots:
            allowed = ', '.join(slots) if slots else 'none'
            raise UnknownFieldError(f"'{path}' is not a field of {_type_name(type(msg))} "
                                    f'(fields: {allowed})')
        slot = slots[key]
        stamp = _stamp_setter(msg, key, slot, value, expand)
        if stamp is not None:
            stamps.append(stamp)
            continue
        setattr(msg, key, _convert(slot, value, getattr(msg, key), path, expand, stamps))


def _stamp_setter(msg: Any, key: str, slot: Any, value: Any,
                  expand: tuple[bool, bool]) -> Callable[[Any], None] | None:
    """For a Header given as 'auto' / a Time given as 'now' (when expanded), its setter."""
    if not isinstance(slot, definition.NamespacedType) or not isinstance(value, str):
        return None
    name = '/'.join(slot.namespaced_name())
    if expand[0] and value == 'auto' and name == 'std_msgs/msg/Header':
        return partial(setattr, getattr(msg, key), 'stamp')
    if expand[1] and value == 'now' and name == 'builtin_interfaces/msg/Time':
        return partial(setattr, msg, key)
    return None


def _show(value: Any) -> str:
    return 'nothing (null)' if value is None else repr(value)


def _convert(slot: Any, value: Any, current: Any, path: str, expand: tuple[bool, bool],
             stamps: list) -> Any:
    if isinstance(slot, definition.AbstractNestedType):
        return _convert_sequence(slot, value, path, expand, stamps)
    if isinstance(slot, definition.NamespacedType):
        cls = import_message_from_namespaced_type(slot)
        if isinstance(value, cls):
            return value
        target = current if current is not None else cls()
        _set_fields(target, value, f'{path}.', expand, stamps)
        return target
    if isinstance(slot, (definition.AbstractString, definition.AbstractWString)):
        return _checked_string(slot, value, path)
    return _checked_basic(getattr(slot, 'typename', None), value, path)


def _convert_sequence(slot: Any, value: Any, path: str, expand: tuple[bool, bool],
                      stamps: list) -> Any:
    if not is_sequence(value):
        raise FieldError(f"'{path}' must be a list, got {_show(value)}")
    if isinstance(slot, definition.Array) and len(value) != slot.size:
        raise FieldError(f"'{path}' must have exactly {slot.size} elements, got {len(value)}")
    if isinstance(slot, definition.BoundedSequence) and len(value) > slot.maximum_size:
        raise FieldError(f"'{path}' can hold at most {slot.maximum_size} elements, "
                         f'got {len(value)}')
    element = slot.value_type
    if isinstance(element, definition.NamespacedType):
        cls = import_message_from_namespaced_type(element)
        return [_convert(element, item, cls(), f'{path}[{index}]', expand, stamps)
                for index, item in enumerate(value)]
    return [_convert(element, item, None, f'{path}[{index}]', expand, stamps)
            for index, item in enumerate(value)]


def _checked_string(slot: Any, value: Any, path: str) -> str:
    if not isinstance(value, str):
        raise FieldError(f"'{path}' must be a string, got {_show(value)} "
                         "(quote it, e.g. '\"123\"')")
    limit = getattr(slot, 'maximum_size', None)
    if isinstance(limit, int) and len(value) > limit:
        raise FieldError(f"'{path}' can hold at most {limit} characters, got {len(value)}")
    return value


def _checked_basic(name: str | None, value: Any, path: str) -> Any:
    if name == 'boolean':
        if not (isinstance(value, bool) or is_numpy(value, 'bool_')):
            raise FieldError(f"'{path}' must be a boolean (true or false), got {_show(value)}")
        return bool(value)
    if name in INTEGER_RANGES:
        return _checked_integer(name, value, path)
    if name in FLOAT_TYPES:
        if isinstance(value, bool) or not isinstance(value, numbers.Real):
            raise FieldError(f"'{path}' must be a number, got {_show(value)}")
        number = float(value)
        if name in ('float', 'float32') and FLOAT32_MAX < abs(number) < float('inf'):
            raise FieldError(f"'{path}' must be a float32 in [-{FLOAT32_MAX:g}, "
                             f'{FLOAT32_MAX:g}], got {_show(value)}')
        return number
    if name in ('char', 'wchar'):
        if isinstance(value, str) and len(value) == 1:
            return value
        raise FieldError(f"'{path}' must be a single character, got {_show(value)}")
    return value


def _checked_integer(name: str, value: Any, path: str) -> Any:
    if name == 'octet' and isinstance(value, bytes) and len(value) == 1:
        return value  # what an octet field holds and gives back
    low, high = INTEGER_RANGES[name]
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) \
            or not low <= value <= high:
        raise FieldError(f"'{path}' must be an integer in [{low}, {high}], got {_show(value)}")
    return bytes([value]) if name == 'octet' else int(value)


def _type_name(msg_class: Any) -> str:
    """'pkg/msg/Name' of a generated class (a service's parts: 'pkg/srv/Name_Request')."""
    module = msg_class.__module__.split('.')
    if len(module) < 2:  # not a generated class
        return f'{msg_class.__module__}.{msg_class.__name__}'
    return f'{module[0]}/{module[1]}/{msg_class.__name__}'
