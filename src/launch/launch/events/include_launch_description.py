"""IncludeLaunchDescription: asks the running launch to visit a launch description."""

from typing import Any

from launch.event import Event


class IncludeLaunchDescription(Event):
    name = 'launch.events.IncludeLaunchDescription'

    def __init__(self, launch_description: Any) -> None:
        self.__launch_description = launch_description

    @property
    def launch_description(self) -> Any:
        return self.__launch_description
