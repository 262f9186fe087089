"""launch.conditions: IfCondition, UnlessCondition and configuration comparisons."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

from launch._missing import module_getattr
from launch.condition import Condition
from launch.substitution import (
    SomeSubstitutionsType,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext

_TRUE = ('true', '1')
_FALSE = ('false', '0')


class InvalidConditionExpressionError(ValueError):
    def __init__(self, expression: str) -> None:
        super().__init__(f"invalid condition expression '{expression}': expected one of "
                         f"{list(_TRUE + _FALSE)} (any letter case)")


def evaluate_condition_expression(context: LaunchContext, expression: list) -> bool:
    text = perform_substitutions(context, expression).strip()
    if text.lower() in _TRUE:
        return True
    if text.lower() in _FALSE:
        return False
    raise InvalidConditionExpressionError(text)


class IfCondition(Condition):
    """True when the expression is 'true' or '1'."""

    def __init__(self, predicate_expression: SomeSubstitutionsType) -> None:
        self.expression = normalize_to_list_of_substitutions(predicate_expression)
        super().__init__(predicate=lambda context: evaluate_condition_expression(
            context, self.expression))


class UnlessCondition(Condition):
    """True when the expression is 'false' or '0'."""

    def __init__(self, predicate_expression: SomeSubstitutionsType) -> None:
        self.expression = normalize_to_list_of_substitutions(predicate_expression)
        super().__init__(predicate=lambda context: not evaluate_condition_expression(
            context, self.expression))


class LaunchConfigurationEquals(Condition):
    def __init__(self, launch_configuration_name: str, expected_value: SomeSubstitutionsType
                 ) -> None:
        self.name = launch_configuration_name
        self.expected = (None if expected_value is None
                         else normalize_to_list_of_substitutions(expected_value))
        super().__init__(predicate=self._equal)

    def _equal(self, context: LaunchContext) -> bool:
        value = context.launch_configurations.get(self.name)
        expected = None if self.expected is None else perform_substitutions(context,
                                                                             self.expected)
        return value == expected


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    def _equal(self, context: LaunchContext) -> bool:
        return not super()._equal(context)


__all__ = ['IfCondition', 'InvalidConditionExpressionError', 'LaunchConfigurationEquals',
           'LaunchConfigurationNotEquals', 'UnlessCondition', 'evaluate_condition_expression']

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
