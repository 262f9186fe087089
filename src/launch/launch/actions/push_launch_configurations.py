"""PushLaunchConfigurations: saves the configurations, for a later PopLaunchConfigurations."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.action import Action

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class PushLaunchConfigurations(Action):
    def execute(self, context: LaunchContext) -> None:
        context._push_launch_configurations()
