"""ProcessTargetedEvent: an event meant for the processes its matcher accepts."""

from collections.abc import Callable
from typing import Any

from launch.event import Event


class ProcessTargetedEvent(Event):
    name = 'launch.events.process.ProcessTargetedEvent'

    def __init__(self, *, process_matcher: Callable[[Any], bool]) -> None:
        self.__process_matcher = process_matcher

    @property
    def process_matcher(self) -> Callable[[Any], bool]:
        return self.__process_matcher
