"""Parameter declarations that turn bad input into one line instead of a dead node.

rclpy raises out of declare_parameter when a params file or `-p` gives a value of the wrong
type, and ignores a name no one declares. A Nav2 server here declares through
declare_checked (a wrong type: one error line, the default stays) and, once everything is
declared, calls warn_unknown_parameters (each name it does not know: one warning line).
"""

from __future__ import annotations

from typing import Any

from rclpy.exceptions import InvalidParameterTypeException, InvalidParameterValueException
from rclpy.node import Node
from rclpy.parameter import Parameter

# What every node has without declaring it (rclpy's own, the rclcpp-parity QoS overrides).
IMPLICIT = ('use_sim_time', 'start_type_description_service')
IMPLICIT_PREFIXES = ('qos_overrides.',)

_TYPE_WORDS = {
    Parameter.Type.BOOL: 'a bool (true/false)',
    Parameter.Type.INTEGER: 'an integer',
    Parameter.Type.DOUBLE: 'a number',
    Parameter.Type.STRING: 'a string',
    Parameter.Type.STRING_ARRAY: 'a list of strings',
    Parameter.Type.DOUBLE_ARRAY: 'a list of numbers',
    Parameter.Type.INTEGER_ARRAY: 'a list of integers',
    Parameter.Type.BOOL_ARRAY: 'a list of bools',
}


def type_words(kind: Parameter.Type) -> str:
    return _TYPE_WORDS.get(kind, kind.name.lower())


def declare_checked(node: Node, name: str, default: Any) -> Any:
    """Declare `name` with `default` (a value, or a Parameter.Type for "no default") and
    return its value; an override of the wrong type is refused in one line."""
    expected = default if isinstance(default, Parameter.Type) else \
        Parameter.Type.from_parameter_value(default)
    override = node._parameter_overrides.get(name)  # what --params-file and -p gave
    if (override is not None and expected == Parameter.Type.DOUBLE
            and override.type_ == Parameter.Type.INTEGER):
        # `bond_timeout: 4` means 4.0: a params file author should not need the dot
        node._parameter_overrides[name] = Parameter(name, value=float(override.value))
    try:
        return node.declare_parameter(name, default).value
    except (InvalidParameterTypeException, InvalidParameterValueException):
        shown = 'no default' if isinstance(default, Parameter.Type) else f'the default {default!r}'
        node.get_logger().error(
            f"Parameter '{name}' must be {type_words(expected)}, got {override.value!r}: "
            f'using {shown}')
        return node.declare_parameter(name, default, ignore_override=True).value


def warn_unknown_parameters(node: Node) -> list[str]:
    """One warning per name given to this node that it does not declare; returns them."""
    unknown = sorted(name for name in node._parameter_overrides
                     if not node.has_parameter(name) and name not in IMPLICIT
                     and not name.startswith(IMPLICIT_PREFIXES))
    if unknown:
        known = ', '.join(sorted(name for name in node._parameters
                                 if name not in IMPLICIT and not name.startswith(
                                     IMPLICIT_PREFIXES)))
        for name in unknown:
            node.get_logger().warning(
                f"Ignoring unknown parameter '{name}' (parameters of {node.get_name()}: "
                f'{known})')
    return unknown
