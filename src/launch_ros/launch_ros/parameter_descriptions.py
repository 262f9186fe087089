"""Parameter values and files for Node(parameters=[...])."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

import yaml
from launch._missing import module_getattr
from launch.substitution import (
    Substitution,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class ParameterValue:
    """A parameter value given by substitutions; read as YAML unless value_type is str."""

    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        self.value = value
        self.value_type = value_type

    def evaluate(self, context: LaunchContext) -> Any:
        value = evaluate_value(context, self.value)
        if isinstance(value, str) and self.value_type is not str and _is_substituted(
                self.value):
            value = yaml.safe_load(value) if value else value
        if self.value_type in (int, float, bool) and not isinstance(value, self.value_type):
            value = self.value_type(value)
        return value


class ParameterFile:
    def __init__(self, param_file: Any, *, allow_substs: bool = False) -> None:
        self.param_file = param_file
        self.allow_substs = allow_substs

    def evaluate(self, context: LaunchContext) -> str:
        return evaluate_value(context, self.param_file)


def _is_substituted(value: Any) -> bool:
    return not isinstance(value, str)


def evaluate_value(context: LaunchContext, value: Any) -> Any:
    """A parameter value with its substitutions performed."""
    if isinstance(value, ParameterValue):
        return value.evaluate(context)
    if isinstance(value, (str, bool, int, float)) or value is None:
        return value
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    if isinstance(value, Substitution):
        return _yaml_or_text(perform_substitutions(context, [value]))
    if isinstance(value, (list, tuple)):
        if value and all(isinstance(v, (str, Substitution)) for v in value) and any(
                isinstance(v, Substitution) for v in value):
            # A list mixing text and substitutions is one value, concatenated (upstream).
            return _yaml_or_text(perform_substitutions(
                context, normalize_to_list_of_substitutions(value)))
        return [evaluate_value(context, v) for v in value]
    raise TypeError(f'unsupported parameter value {value!r} ({type(value).__name__})')


def _yaml_or_text(text: str) -> Any:
    try:
        return yaml.safe_load(text) if text else text
    except yaml.YAMLError:
        return text


__getattr__ = module_getattr(__name__)
