"""Forms generated from interface types, and the checks on what comes back from them.

A form is described to the page as a list of fields (name, ROS type, kind, range, default);
what the page sends back goes through rosidl_runtime_py's set_message_fields, the same validation as
`ros2 service call` (type, range, unknown fields), before anything reaches ROS.
"""

from __future__ import annotations

from typing import Any

from rosidl_runtime_py.set_message import FLOAT32_MAX, INTEGER_RANGES, FieldError

from rosidl_runtime_py import message_to_ordereddict, set_message_fields, utilities


class FormError(ValueError):
    """Bad input from a form: the message is shown in the page as is."""


def topic_name_problem(name: str) -> str | None:
    """Why `name` is no valid fully qualified topic name (rclpy's words), or None."""
    from rclpy.validate_full_topic_name import validate_full_topic_name
    try:
        validate_full_topic_name(name)
    except Exception as error:  # rclpy's InvalidTopicNameException and friends
        return str(error)
    return None


def check_topic_name(name: str) -> None:
    """FormError naming `name` and rclpy's reason when it is no valid fully qualified topic
    name: checked before a publisher is made, since rclpy raises on a bad name."""
    problem = topic_name_problem(name)
    if problem is not None:
        raise FormError(f'invalid topic name {name!r}: {problem}')


MAX_TOPIC = 256  # characters of a topic name (or frame id) the RViz page's routes accept


def absolute_topic(topic: str) -> bool:
    """A topic name a subscription or publisher can have (rclpy would raise on any other)."""
    return len(topic) <= MAX_TOPIC and topic_name_problem(topic) is None


def interface_class(name: str, kind: str) -> Any:
    getters = {'msg': utilities.get_message, 'srv': utilities.get_service,
               'action': utilities.get_action}
    if kind not in getters:
        raise FormError(f"unknown interface kind '{kind}' (allowed: msg, srv, action)")
    getter = getters[kind]
    try:
        return getter(name)
    except (ImportError, AttributeError, ValueError):
        raise FormError(f"unknown {kind} type '{name}'") from None


def describe(msg_class: Any) -> list[dict]:
    """The fields of a message class, as the page builds its form from them."""
    from rosidl_parser import definition as d

    defaults = msg_class()
    fields = msg_class.get_fields_and_field_types()
    described = []
    for (name, ros_type), slot in zip(fields.items(), msg_class.SLOT_TYPES, strict=True):
        field: dict[str, Any] = {'name': name, 'type': ros_type}
        if isinstance(slot, d.AbstractNestedType):
            field['kind'] = 'array'
            field['default'] = message_to_ordered_value(getattr(defaults, name))
            if isinstance(slot, d.Array):
                field['size'] = slot.size
            elif isinstance(slot, d.BoundedSequence):
                field['max_size'] = slot.maximum_size
        elif isinstance(slot, d.NamespacedType):
            field['kind'] = 'message'
            field['fields'] = describe(interface_class('/'.join([*slot.namespaces, slot.name]),
                                                       slot.namespaces[-1]))
        elif isinstance(slot, (d.AbstractString, d.AbstractWString)):
            field['kind'] = 'string'
            field['default'] = getattr(defaults, name)
            limit = getattr(slot, 'maximum_size', None)
            if isinstance(limit, int):
                field['max_length'] = limit
        else:
            typename = getattr(slot, 'typename', '')
            value = getattr(defaults, name)
            if typename == 'boolean':
                field['kind'] = 'bool'
            elif typename in INTEGER_RANGES:
                field['kind'] = 'int'
                field['min'], field['max'] = INTEGER_RANGES[typename]
                value = value[0] if isinstance(value, bytes) else value
            elif typename in ('float', 'float32'):
                field.update(kind='float', min=-FLOAT32_MAX, max=FLOAT32_MAX)
            elif typename in ('double', 'float64', 'long double'):
                field['kind'] = 'float'
            else:
                field['kind'] = 'string'
                field['max_length'] = 1
            field['default'] = value
        described.append(field)
    return described


def message_to_ordered_value(value: Any) -> Any:
    if hasattr(value, 'get_fields_and_field_types'):
        return message_to_ordereddict(value)
    if isinstance(value, (bytes, str, bool, int, float)):
        return value
    try:
        return [message_to_ordered_value(v) for v in value]
    except TypeError:
        return value


def build(msg_class: Any, values: Any) -> Any:
    """A message of `msg_class` filled from the form's values; FormError names the field."""
    msg = msg_class()
    try:
        set_message_fields(msg, values if values is not None else {})
    except FieldError as error:
        raise FormError(error.explanation) from None
    return msg


# --------------------------------------------------------------------------------------
# Parameters (rcl_interfaces)
# --------------------------------------------------------------------------------------

TYPE_NAMES = {1: 'bool', 2: 'integer', 3: 'double', 4: 'string', 5: 'byte_array',
              6: 'bool_array', 7: 'integer_array', 8: 'double_array', 9: 'string_array'}
VALUE_FIELDS = {1: 'bool_value', 2: 'integer_value', 3: 'double_value', 4: 'string_value',
                5: 'byte_array_value', 6: 'bool_array_value', 7: 'integer_array_value',
                8: 'double_array_value', 9: 'string_array_value'}


def parameter_value_to_plain(value: Any) -> Any:
    field = VALUE_FIELDS.get(value.type)
    if field is None:
        return None
    plain = getattr(value, field)
    return plain if isinstance(plain, (bool, int, float, str)) else list(plain)


def describe_parameter(descriptor: Any, value: Any) -> dict:
    info = {'name': descriptor.name, 'type': TYPE_NAMES.get(value.type, 'not set'),
            'value': parameter_value_to_plain(value), 'description': descriptor.description,
            'read_only': descriptor.read_only}
    if descriptor.integer_range:
        r = descriptor.integer_range[0]
        info['range'] = {'min': r.from_value, 'max': r.to_value, 'step': r.step}
    elif descriptor.floating_point_range:
        r = descriptor.floating_point_range[0]
        info['range'] = {'min': r.from_value, 'max': r.to_value, 'step': r.step}
    return info


def parameter_value(info: dict, raw: Any) -> Any:
    """An rcl_interfaces ParameterValue for `raw`, checked against the parameter's type and
    descriptor range (`info` as describe_parameter made it); FormError otherwise."""
    from rcl_interfaces.msg import ParameterValue

    name, kind = info['name'], info['type']
    if info.get('read_only'):
        raise FormError(f"parameter '{name}' is read-only")
    value = ParameterValue()
    if kind == 'bool':
        if not isinstance(raw, bool):
            raise FormError(f"parameter '{name}' must be a boolean (true or false), got {raw!r}")
        value.type, value.bool_value = 1, raw
    elif kind == 'integer':
        if isinstance(raw, bool) or not isinstance(raw, int):
            raise FormError(f"parameter '{name}' must be an integer, got {raw!r}")
        _check_range(name, raw, info.get('range'))
        value.type, value.integer_value = 2, raw
    elif kind == 'double':
        if isinstance(raw, bool) or not isinstance(raw, (int, float)):
            raise FormError(f"parameter '{name}' must be a number, got {raw!r}")
        _check_range(name, float(raw), info.get('range'))
        value.type, value.double_value = 3, float(raw)
    elif kind == 'string':
        if not isinstance(raw, str):
            raise FormError(f"parameter '{name}' must be a string, got {raw!r}")
        value.type, value.string_value = 4, raw
    else:
        raise FormError(f"parameter '{name}' is a {kind}: set it with `ros2 param set`")
    return value


def _check_range(name: str, number: float, limits: dict | None) -> None:
    if limits and not limits['min'] <= number <= limits['max']:
        raise FormError(f"parameter '{name}' must be in [{limits['min']}, {limits['max']}], "
                        f'got {number}')
