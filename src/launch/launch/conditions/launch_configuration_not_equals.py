"""LaunchConfigurationNotEquals: the opposite of LaunchConfigurationEquals."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.conditions.launch_configuration_equals import LaunchConfigurationEquals

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    def _predicate_func(self, context: LaunchContext) -> bool:
        return not self._equal(context)
