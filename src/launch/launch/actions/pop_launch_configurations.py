"""PopLaunchConfigurations: restores what the last PushLaunchConfigurations saved."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.action import Action

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class PopLaunchConfigurations(Action):
    def execute(self, context: LaunchContext) -> None:
        context._pop_launch_configurations()
