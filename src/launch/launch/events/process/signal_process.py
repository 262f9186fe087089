"""SignalProcess: send a signal (a name or a signal.Signals) to the matching processes."""

from __future__ import annotations

import signal as signal_module
from collections.abc import Callable
from typing import TYPE_CHECKING

from launch.events.process.process_targeted_event import ProcessTargetedEvent
from launch.utilities import ensure_argument_type

if TYPE_CHECKING:
    from launch.actions.execute_local import ExecuteLocal


class SignalProcess(ProcessTargetedEvent):
    name = 'launch.events.process.SignalProcess'

    def __init__(self, *, signal_number: str | signal_module.Signals,
                 process_matcher: Callable[[ExecuteLocal], bool]) -> None:
        super().__init__(process_matcher=process_matcher)
        ensure_argument_type(signal_number, (str, signal_module.Signals), 'signal_number',
                             'SignalProcess')
        self.__signal = signal_number

    @property
    def signal(self) -> str | signal_module.Signals:
        return self.__signal

    @property
    def signal_name(self) -> str:
        return self.__signal if isinstance(self.__signal, str) else self.__signal.name
