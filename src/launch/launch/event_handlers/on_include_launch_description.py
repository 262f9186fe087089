"""OnIncludeLaunchDescription: visit the description an IncludeLaunchDescription event carries.

The LaunchService registers it, so an event emitted from anywhere (another thread through
LaunchService.emit_event, as launch_testing's tools do) adds entities to a running launch.
"""

from __future__ import annotations

from typing import Any

from launch.event_handler import EventHandler
from launch.events.include_launch_description import IncludeLaunchDescription
from launch.utilities import is_a_subclass


class OnIncludeLaunchDescription(EventHandler):
    def __init__(self, **kwargs: Any) -> None:
        from launch.actions.opaque_function import OpaqueFunction
        super().__init__(
            matcher=lambda event: is_a_subclass(event, IncludeLaunchDescription),
            entities=OpaqueFunction(
                function=lambda context: [context.locals.event.launch_description]),
            **kwargs)

    @property
    def handler_description(self) -> str:
        return 'returns the launch_description in the event'

    @property
    def matcher_description(self) -> str:
        return 'event issubclass of launch.events.IncludeLaunchDescription'
