"""LaunchConfigurationEquals: a launch configuration has a value (or, with None, is unset).

Deprecated upstream in favour of IfCondition(EqualsSubstitution(...)); kept, with its warning.
"""

from __future__ import annotations

import warnings
from typing import TYPE_CHECKING

from launch.condition import Condition
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType

_DEPRECATION = (
    "The 'LaunchConfigurationEquals' and 'LaunchConfigurationNotEquals' Conditions are  "
    "deprecated. Use the 'EqualsSubstitution' and 'NotEqualsSubstitution' substitutions "
    "instead! E.g.:\n  IfCondition(\n  \tEqualsSubstitution(LaunchConfiguration("
    "'some_launch_arg'), \"some_equality_check\")\n  )")


class LaunchConfigurationEquals(Condition):
    def __init__(self, launch_configuration_name: str,
                 expected_value: SomeSubstitutionsType | None) -> None:
        warnings.warn(_DEPRECATION, UserWarning, stacklevel=2)
        self._name = launch_configuration_name
        self._expected = (None if expected_value is None
                          else normalize_to_list_of_substitutions(expected_value))
        super().__init__(predicate=self._predicate_func)

    def _equal(self, context: LaunchContext) -> bool:
        expected = (None if self._expected is None
                    else perform_substitutions(context, self._expected))
        if self._name not in context.launch_configurations:
            return expected is None
        return context.launch_configurations[self._name] == expected

    def _predicate_func(self, context: LaunchContext) -> bool:
        return self._equal(context)

    def describe(self) -> str:
        return repr(self)
