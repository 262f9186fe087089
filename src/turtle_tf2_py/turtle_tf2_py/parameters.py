"""Parameters the tutorial nodes declare, checked: a wrong type or range is one error line.

Launch files and `-p name:=value` give YAML-typed values (`timeout:=0` is an integer, a
frame named `1` too): the nodes declare them with dynamic typing and check them here, so a
bad value is reported by name and the default used, instead of the node dying.
"""

from __future__ import annotations

import math

from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node


def declare_frame(node: Node, name: str, default: str) -> str:
    """A frame id parameter; a value that is not a string gets one error line and the default."""
    value = node.declare_parameter(
        name, default, ParameterDescriptor(dynamic_typing=True)).value
    if not isinstance(value, str):
        node.get_logger().error(f'{name} must be a frame id (a string), got {value!r}; '
                                f'using {default!r}')
        return default
    return value


def declare_seconds(node: Node, name: str, default: float, maximum: float) -> float:
    """A duration parameter in seconds; `name:=0` (an integer) counts as 0.0 seconds.

    A value that is not a number in [0, maximum] gets one error line and the default.
    """
    value = node.declare_parameter(
        name, default, ParameterDescriptor(dynamic_typing=True)).value
    if isinstance(value, bool) or not isinstance(value, (int, float)) \
            or not (math.isfinite(value) and 0.0 <= value <= maximum):
        node.get_logger().error(f'{name} must be a number of seconds between 0.0 and '
                                f'{maximum}, got {value!r}; using {default}')
        return default
    return float(value)
