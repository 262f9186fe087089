"""What the `ros2` verbs add to rosidl_runtime_py's conversion: parsing a command line's YAML
(keys stay strings, errors on one line) and populating a message from it with
`Failed to populate field: ...` errors (`topic pub`, `service call`, `action send_goal`).

Messages to YAML and the field checks themselves are rosidl_runtime_py's (the one
implementation rqt_web, ros2bag and foxglove_bridge use too).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from rosidl_runtime_py.convert import dump_yaml as to_yaml
from rosidl_runtime_py.set_message import FieldError, set_message_fields

from ros2cli.verb_context import CliError

__all__ = ['load_values', 'populate', 'to_yaml', 'yaml_problem']


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


def populate(msg: Any, text: str, stamps: list[Callable[[Any], None]] | None = None) -> Any:
    """Fill `msg` from a YAML mapping; CliError('Failed to populate field: ...') on bad input.

    With `stamps` (a list), a std_msgs/Header given as 'auto' and a builtin_interfaces/Time
    given as 'now' are accepted (as `ros2 topic pub` does): their setters, taking a Time
    message, are appended to it (set_message_fields' expand_header_auto/expand_time_now).
    """
    values = load_values(text)
    if values is None or values == '':
        values = {}
    if not isinstance(values, dict):
        raise CliError('The passed value needs to be a dictionary in YAML format')
    try:
        setters = set_message_fields(msg, values, expand_header_auto=stamps is not None,
                                     expand_time_now=stamps is not None)
    except FieldError as error:
        raise CliError(f'Failed to populate field: {error.explanation}') from None
    if stamps is not None:
        stamps.extend(setters)
    return msg
