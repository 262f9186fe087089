"""SetEnvironmentVariable: `<set_env name= value=/>`, for the processes started after it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.actions._name_value_action import NameValueAction
from launch.frontend.expose import expose_action

if TYPE_CHECKING:
    from collections.abc import MutableMapping

    from launch.launch_context import LaunchContext


@expose_action('set_env')
class SetEnvironmentVariable(NameValueAction):
    @staticmethod
    def _mapping(context: LaunchContext) -> MutableMapping[str, str]:
        return context.environment
