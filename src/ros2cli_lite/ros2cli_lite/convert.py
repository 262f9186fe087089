"""Messages <-> YAML, with rosidl_runtime_py's names (message_to_yaml, message_to_ordereddict,
set_message_fields): what `ros2 topic echo/pub`, `service call`, `action send_goal`, rqt and
the bag tools print and parse.

Bad values are refused with one line naming the field and what it can hold (FieldError).
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable
from typing import Any

from ros2cli_lite.api import CliError, type_name

# --------------------------------------------------------------------------------------
# Message -> plain data / YAML
# --------------------------------------------------------------------------------------

def message_to_ordereddict(msg: Any) -> dict:
    """The fields of `msg` as plain data (dicts in field order, lists, numbers, text)."""
    return {field: _plain(getattr(msg, field)) for field in msg.get_fields_and_field_types()}


def _plain(value: Any) -> Any:
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, bytes):
        return ''.join(chr(c) for c in value)
    if isinstance(value, (list, tuple)) or type(value).__name__ in ('array', 'ndarray'):
        return [_plain(v) for v in value]
    if hasattr(value, 'get_fields_and_field_types'):
        return message_to_ordereddict(value)
    if hasattr(value, 'item'):  # numpy scalar
        return value.item()
    return value


def _dumper() -> Any:
    import yaml

    class OrderedDumper(yaml.SafeDumper):
        pass

    def represent_dict(dumper: Any, data: dict) -> Any:
        # A node without a flow style: mappings stay in block style even with flow_style
        # (only sequences flow), as rosidl_runtime_py's message_to_yaml prints them.
        return yaml.MappingNode('tag:yaml.org,2002:map', [
            (dumper.represent_data(key), dumper.represent_data(value))
            for key, value in data.items()])

    OrderedDumper.add_representer(dict, represent_dict)
    return OrderedDumper


def to_yaml(data: Any, flow_style: bool = False) -> str:
    """PyYAML block style in field order, as rosidl_runtime_py's message_to_yaml."""
    import yaml
    return yaml.dump(data, Dumper=_dumper(), allow_unicode=True, width=sys.maxsize,
                     default_flow_style=flow_style)


def message_to_yaml(msg: Any, flow_style: bool = False) -> str:
    return to_yaml(message_to_ordereddict(msg), flow_style)


# --------------------------------------------------------------------------------------
# YAML -> message, with validation
# --------------------------------------------------------------------------------------

def load_values(text: str) -> Any:
    """Parse YAML where mapping keys are always strings: `{off: 1}` is the field `off`.

    PyYAML follows YAML 1.1, where an unquoted `off`/`on`/`yes`/`no` is a boolean; as a key
    that would never match a field name. Values keep the usual resolution.
    """
    import yaml

    class KeysAsStrings(yaml.SafeLoader):
        def construct_mapping(self, node: Any, deep: bool = False) -> dict:
            if isinstance(node, yaml.MappingNode):
                self.flatten_mapping(node)
            mapping = {}
            for key_node, value_node in node.value:
                if isinstance(key_node, yaml.ScalarNode):
                    key = key_node.value
                else:
                    key = self.construct_object(key_node, deep=deep)
                mapping[key] = self.construct_object(value_node, deep=deep)
            return mapping

    KeysAsStrings.add_constructor('tag:yaml.org,2002:map', KeysAsStrings.construct_yaml_map)
    try:
        return yaml.load(text, Loader=KeysAsStrings)
    except yaml.YAMLError as error:
        raise CliError(f'The passed value is not valid YAML: {yaml_problem(error)}') from None


def yaml_problem(error: Any) -> str:
    """A PyYAML error on one line: what is wrong and where (PyYAML spreads it over five)."""
    problem = getattr(error, 'problem', None)
    mark = getattr(error, 'problem_mark', None)
    if not problem:
        return ' '.join(str(error).split())
    if mark is None:
        return problem
    return f'{problem} (line {mark.line + 1}, column {mark.column + 1})'


INTEGER_RANGES = {
    'int8': (-(2**7), 2**7 - 1), 'uint8': (0, 2**8 - 1), 'octet': (0, 2**8 - 1),
    'int16': (-(2**15), 2**15 - 1), 'uint16': (0, 2**16 - 1),
    'int32': (-(2**31), 2**31 - 1), 'uint32': (0, 2**32 - 1),
    'int64': (-(2**63), 2**63 - 1), 'uint64': (0, 2**64 - 1),
}
FLOAT32_MAX = 3.4028234663852886e38
FLOAT_TYPES = ('float', 'double', 'float32', 'float64', 'long double')


class FieldError(ValueError):
    pass


def set_message_fields(msg: Any, values: Any, prefix: str = '',
                 stamps: list[Callable[[Any], None]] | None = None) -> None:
    """Set the fields of `msg` from a mapping, refusing anything the field cannot hold.

    With `stamps` (a list), a std_msgs/Header given as 'auto' and a builtin_interfaces/Time
    given as 'now' are accepted (as `ros2 topic pub` does): a setter that stamps the field
    with a given Time message is appended for each, to call before every publication.
    """
    if not isinstance(values, dict):
        raise FieldError(f"'{prefix or type_name(type(msg))}' expects a mapping of field names "
                         f'to values, got {_show(values)}')
    fields = list(msg.get_fields_and_field_types())
    slot_types = dict(zip(fields, msg.SLOT_TYPES, strict=True))
    for key, value in values.items():
        path = f'{prefix}{key}'
        if key not in slot_types:
            allowed = ', '.join(fields) if fields else 'none'
            raise FieldError(f"'{path}' is not a field of {type_name(type(msg))} "
                             f'(fields: {allowed})')
        current = getattr(msg, key)
        setattr(msg, key, _convert(slot_types[key], value, current, path, stamps))


def _show(value: Any) -> str:
    if value is None:
        return 'nothing (null)'
    return repr(value)


def _convert(slot_type: Any, value: Any, current: Any, path: str,
             stamps: list[Callable[[Any], None]] | None = None) -> Any:
    from rosidl_parser import definition as d

    if isinstance(slot_type, d.AbstractNestedType):
        if not isinstance(value, list):
            raise FieldError(f"'{path}' must be a list, got {_show(value)}")
        if isinstance(slot_type, d.Array) and len(value) != slot_type.size:
            raise FieldError(f"'{path}' must have exactly {slot_type.size} elements, "
                             f'got {len(value)}')
        if isinstance(slot_type, d.BoundedSequence) and len(value) > slot_type.maximum_size:
            raise FieldError(f"'{path}' can hold at most {slot_type.maximum_size} elements, "
                             f'got {len(value)}')
        element = slot_type.value_type
        if isinstance(element, d.NamespacedType):
            cls = _namespaced_class(element)
            return [_convert(element, v, cls(), f'{path}[{i}]', stamps)
                    for i, v in enumerate(value)]
        return [_convert(element, v, None, f'{path}[{i}]') for i, v in enumerate(value)]
    if isinstance(slot_type, d.NamespacedType):
        target = current if current is not None else _namespaced_class(slot_type)()
        stamp_setter = _stamp_setter(slot_type, value, target) if stamps is not None else None
        if stamp_setter is not None:
            stamps.append(stamp_setter)
            return target
        set_message_fields(target, value, prefix=f'{path}.', stamps=stamps)
        return target
    if isinstance(slot_type, (d.AbstractString, d.AbstractWString)):
        if not isinstance(value, str):
            raise FieldError(f"'{path}' must be a string, got {_show(value)} "
                             "(quote it, e.g. '\"123\"')")
        limit = getattr(slot_type, 'maximum_size', None)
        if isinstance(limit, int) and len(value) > limit:
            raise FieldError(f"'{path}' can hold at most {limit} characters, got {len(value)}")
        return value
    name = getattr(slot_type, 'typename', None)
    if name == 'boolean':
        if not isinstance(value, bool):
            raise FieldError(f"'{path}' must be a boolean (true or false), got {_show(value)}")
        return value
    if name in INTEGER_RANGES:
        low, high = INTEGER_RANGES[name]
        if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
            raise FieldError(f"'{path}' must be an integer in [{low}, {high}], got {_show(value)}")
        return value if name != 'octet' else bytes([value])
    if name in FLOAT_TYPES:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise FieldError(f"'{path}' must be a number, got {_show(value)}")
        number = float(value)
        if name in ('float', 'float32') and abs(number) > FLOAT32_MAX \
                and abs(number) != float('inf'):
            raise FieldError(f"'{path}' must be a float32 in [-{FLOAT32_MAX:g}, "
                             f'{FLOAT32_MAX:g}], got {_show(value)}')
        return number
    if name in ('char', 'wchar'):
        if isinstance(value, str) and len(value) == 1:
            return value
        raise FieldError(f"'{path}' must be a single character, got {_show(value)}")
    return value


def _stamp_setter(slot_type: Any, value: Any, target: Any) -> Callable[[Any], None] | None:
    """For Header 'auto' / Time 'now', a setter stamping `target` with a Time message."""
    name = '/'.join((*slot_type.namespaces, slot_type.name))
    if name == 'std_msgs/msg/Header' and value == 'auto':
        def stamp_header(now: Any) -> None:
            target.stamp = now
        return stamp_header
    if name == 'builtin_interfaces/msg/Time' and value == 'now':
        def stamp_time(now: Any) -> None:
            target.sec, target.nanosec = now.sec, now.nanosec
        return stamp_time
    return None


def _namespaced_class(slot_type: Any) -> Any:
    module = importlib.import_module('.'.join(slot_type.namespaces))
    return getattr(module, slot_type.name)


def populate(msg: Any, text: str, stamps: list[Callable[[Any], None]] | None = None) -> Any:
    """Fill `msg` from a YAML mapping; CliError('Failed to populate field: ...') on bad input.

    `stamps`: see set_message_fields.
    """
    values = load_values(text)
    if values is None or values == '':
        values = {}
    if not isinstance(values, dict):
        raise CliError('The passed value needs to be a dictionary in YAML format')
    try:
        set_message_fields(msg, values, stamps=stamps)
    except FieldError as error:
        raise CliError(f'Failed to populate field: {error}') from None
    return msg
