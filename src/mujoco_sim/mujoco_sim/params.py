"""The simulator's parameters, checked where they enter: one line naming the parameter and
what is allowed, instead of rclpy's type error or a crash later. Numbers take an integer or
a float alike (`real_time_factor:=2` and `:=2.0`), as a learner types them."""

from __future__ import annotations

import math

from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node


class ParameterError(ValueError):
    """str() is one line: the parameter, its value and what is allowed."""


class Parameters:
    def __init__(self, node: Node) -> None:
        self.node = node

    def _declare(self, name: str, default):
        descriptor = ParameterDescriptor(dynamic_typing=True)
        return self.node.declare_parameter(name, default, descriptor).value

    def text(self, name: str, default: str) -> str:
        value = self._declare(name, default)
        if not isinstance(value, str):
            raise ParameterError(f'{name} is {value!r}; allowed: a string')
        return value

    def flag(self, name: str, default: bool) -> bool:
        value = self._declare(name, default)
        if not isinstance(value, bool):
            raise ParameterError(f'{name} is {value!r}; allowed: true or false')
        return value

    def number(self, name: str, default: float, low: float = -math.inf,
               high: float = math.inf, integer: bool = False) -> float:
        value = self._declare(name, default)
        kinds = (int,) if integer else (int, float)
        allowed = f"{'an integer' if integer else 'a number'}"
        if math.isfinite(low) or math.isfinite(high):
            allowed += f' from {low:g} to {high:g}'
        if (isinstance(value, bool) or not isinstance(value, kinds)
                or not math.isfinite(value) or not low <= value <= high):
            raise ParameterError(f'{name} is {value!r}; allowed: {allowed}')
        return int(value) if integer else float(value)
