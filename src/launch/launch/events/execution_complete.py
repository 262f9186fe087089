"""ExecutionComplete: an action has done its work (a process action: its process ended)."""

from typing import Any

from launch.event import Event


class ExecutionComplete(Event):
    name = 'launch.events.ExecutionComplete'

    def __init__(self, *, action: Any) -> None:
        self.__action = action

    @property
    def action(self) -> Any:
        return self.__action
