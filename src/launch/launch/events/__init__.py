"""launch.events: Shutdown, timer and execution events (process events in .process)."""

from __future__ import annotations

import os
from typing import Any

from launch._missing import module_getattr
from launch.event import Event
from launch.events import process


class Shutdown(Event):
    """Asks the launch to stop: every process gets SIGINT, then SIGTERM, then SIGKILL."""

    name = 'launch.events.Shutdown'

    def __init__(self, *, reason: str = 'reason not given', due_to_sigint: bool = False
                 ) -> None:
        self.reason = reason
        self.due_to_sigint = due_to_sigint


class TimerEvent(Event):
    name = 'launch.events.TimerEvent'

    def __init__(self, *, timer_action: Any) -> None:
        self.timer_action = timer_action


class ExecutionComplete(Event):
    name = 'launch.events.ExecutionComplete'

    def __init__(self, *, action: Any) -> None:
        self.action = action


class IncludeLaunchDescription(Event):
    name = 'launch.events.IncludeLaunchDescription'

    def __init__(self, launch_description: Any) -> None:
        self.launch_description = launch_description


def matches_action(target_action: Any) -> Any:
    return lambda action: action is target_action


__all__ = ['ExecutionComplete', 'IncludeLaunchDescription', 'Shutdown', 'TimerEvent',
           'matches_action', 'process']

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
