"""Messages to plain data: ordered dicts, YAML (block or flow style) and CSV lines.

`truncate_length`, `no_arr` and `no_str` shorten what is shown (as `ros2 topic echo` does):
strings and sequences longer than the length end in '...'; `no_arr` replaces a sequence with a
summary of its type and length, `no_str` a string with its length.
"""

from __future__ import annotations

import array
import sys
from collections import OrderedDict
from functools import cache
from typing import Any

from rosidl_parser import definition

# numpy and yaml are imported when needed, not with this module: `ros2` verbs that only look
# interfaces up (rosidl_runtime_py.utilities) start faster without them.


def is_sequence(value: Any) -> bool:
    """A list, tuple, array.array or numpy array (what a sequence field holds or takes)."""
    return isinstance(value, (list, tuple, array.array)) or is_numpy(value, 'ndarray')


def is_numpy(value: Any, kind: str) -> bool:
    # A numpy value exists only once numpy is imported: no need to import it to check.
    numpy = sys.modules.get('numpy')
    return numpy is not None and isinstance(value, getattr(numpy, kind))


@cache
def _ordered_dumper() -> Any:
    """yaml's default Dumper, with OrderedDicts as plain mappings in their own order.

    The mapping node gets no flow style of its own, so mappings stay in block style even with
    `default_flow_style=True` (only sequences flow), as `ros2 topic echo --flow-style` prints.
    A subclass, so that other users of yaml.dump in the process see no change.
    """
    import yaml

    class OrderedDumper(yaml.Dumper):
        pass

    def represent_ordered(dumper: yaml.Dumper, data: OrderedDict) -> yaml.MappingNode:
        return yaml.MappingNode('tag:yaml.org,2002:map', [
            (dumper.represent_data(key), dumper.represent_data(value))
            for key, value in data.items()])

    OrderedDumper.add_representer(OrderedDict, represent_ordered)
    return OrderedDumper


def dump_yaml(data: Any, flow_style: bool = False) -> str:
    """YAML of data that message_to_ordereddict gave (or built from it), as message_to_yaml."""
    import yaml
    return yaml.dump(data, Dumper=_ordered_dumper(), allow_unicode=True, width=sys.maxsize,
                     default_flow_style=flow_style)


def message_to_yaml(msg: Any, *, truncate_length: int | None = None, no_arr: bool = False,
                    no_str: bool = False, flow_style: bool = False) -> str:
    """The message as YAML, fields in their declared order."""
    return dump_yaml(message_to_ordereddict(msg, truncate_length=truncate_length,
                                            no_arr=no_arr, no_str=no_str), flow_style)


def message_to_csv(msg: Any, *, truncate_length: int | None = None, no_arr: bool = False,
                   no_str: bool = False) -> str:
    """The message's leaf values, depth first, joined with commas (`ros2 topic echo --csv`)."""
    options = {'truncate_length': truncate_length, 'no_arr': no_arr, 'no_str': no_str}
    return ','.join(_csv_value(value, slot, options)
                    for value, slot in _values_and_slots(msg))


def _values_and_slots(msg: Any) -> list[tuple[Any, Any]]:
    return [(getattr(msg, name), slot) for name, slot in get_message_slot_types(msg).items()]


def _csv_value(value: Any, slot: Any, options: dict) -> str:
    limit = options['truncate_length']
    if is_sequence(value):
        if options['no_arr'] and slot is not None:
            return _sequence_summary(value, slot)
        items = []
        for index, item in enumerate(value):
            if limit is not None and index >= limit:
                items.append('...')
                break
            items.append(_csv_value(item, None, options))
        return ','.join(items)
    if isinstance(value, (bool, bytes, float, int, str)) or is_numpy(value, 'number'):
        if options['no_str'] and isinstance(value, str):
            return _string_summary(value)
        if isinstance(value, (bytes, str)) and limit is not None and len(value) > limit:
            value = value[:limit] + (b'...' if isinstance(value, bytes) else '...')
        return str(value)
    return message_to_csv(value, **options)


def message_to_ordereddict(msg: Any, *, truncate_length: int | None = None,
                           no_arr: bool = False, no_str: bool = False) -> OrderedDict:
    """The fields of `msg` as an OrderedDict in declared order: nested messages become
    OrderedDicts, sequences lists, bytes text, numpy scalars Python numbers."""
    return OrderedDict(
        (name, _convert_value(getattr(msg, name, None), field_type=slot,
                              truncate_length=truncate_length, no_arr=no_arr, no_str=no_str))
        for name, slot in get_message_slot_types(msg).items())


def _convert_value(value: Any, *, field_type: Any = None, truncate_length: int | None = None,
                   no_arr: bool = False, no_str: bool = False) -> Any:
    """One value as plain data; `field_type` (the field's rosidl type) is only known for a
    message's own fields, so that no_arr summarises those and not a sequence's items."""
    options = {'truncate_length': truncate_length, 'no_arr': no_arr, 'no_str': no_str}
    if isinstance(value, bytes):
        text = ''.join(chr(c) for c in value[:truncate_length])
        return text + '...' if truncate_length is not None and len(value) > truncate_length \
            else text
    if isinstance(value, str):
        if no_str:
            return _string_summary(value)
        if truncate_length is not None and len(value) > truncate_length:
            return value[:truncate_length] + '...'
        return value
    if is_sequence(value):
        if no_arr and field_type is not None:
            return _sequence_summary(value, field_type)
        # Tuples stay tuples; arrays and ndarrays (one element type each) become lists.
        kind = tuple if isinstance(value, tuple) else list
        truncated = truncate_length is not None and len(value) > truncate_length
        items = [_convert_value(item, **options)
                 for item in (value[:truncate_length] if truncated else value)]
        return kind([*items, '...'] if truncated else items)
    if isinstance(value, dict):
        # Keys are never truncated: two keys could become one.
        converted = OrderedDict() if isinstance(value, OrderedDict) else {}
        for key, item in value.items():
            converted[_convert_value(key)] = _convert_value(item, **options)
        return converted
    if is_numpy(value, 'number'):
        return value.item()
    if isinstance(value, (bool, float, int)) or value is None:
        return value
    return message_to_ordereddict(value, **options)


def _string_summary(value: str) -> str:
    return f'<string length: <{len(value)}>>'


def _sequence_summary(value: Any, field_type: Any) -> str:
    element = _type_name(field_type.value_type)
    if isinstance(field_type, definition.Array):
        return f'<array type: {element}[{field_type.size}]>'
    if isinstance(field_type, definition.BoundedSequence):
        return f'<sequence type: {element}[{field_type.maximum_size}], length: {len(value)}>'
    if isinstance(field_type, definition.UnboundedSequence):
        return f'<sequence type: {element}, length: {len(value)}>'
    return 'unknown'


def _type_name(value_type: Any) -> str:
    if isinstance(value_type, definition.BasicType):
        return value_type.typename
    if isinstance(value_type, definition.AbstractString):
        return 'string'
    if isinstance(value_type, definition.AbstractWString):
        return 'wstring'
    if isinstance(value_type, definition.NamedType):
        return value_type.name
    if isinstance(value_type, definition.NamespacedType):
        return '/'.join(value_type.namespaced_name())
    return 'unknown'


def get_message_slot_types(msg: Any) -> OrderedDict:
    """Field name -> rosidl_parser type, in declared order.

    get_fields_and_field_types() names the types as text; SLOT_TYPES (same length and order,
    by the Python generator) holds the rosidl_parser.definition objects.
    """
    return OrderedDict(zip(msg.get_fields_and_field_types().keys(), msg.SLOT_TYPES, strict=True))
