"""launch.events.process: what happens to a process started by ExecuteProcess."""

from __future__ import annotations

import os
import signal as _signal
from collections.abc import Callable
from typing import Any

from launch._missing import module_getattr
from launch.event import Event


class RunningProcessEvent(Event):
    name = 'launch.events.process.RunningProcessEvent'

    def __init__(self, *, action: Any, name: str, cmd: list[str], cwd: str | None,
                 env: dict[str, str] | None, pid: int) -> None:
        self.action = action
        self.execute_process_action = action
        self.process_name = name
        self.cmd = cmd
        self.cwd = cwd
        self.env = env
        self.pid = pid


class ProcessStarted(RunningProcessEvent):
    name = 'launch.events.process.ProcessStarted'


class ProcessExited(RunningProcessEvent):
    name = 'launch.events.process.ProcessExited'

    def __init__(self, *, returncode: int, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.returncode = returncode


class ProcessIO(RunningProcessEvent):
    name = 'launch.events.process.ProcessIO'

    def __init__(self, *, text: bytes, fd: int, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.text = text
        self.from_stdout = fd == 1
        self.from_stderr = fd == 2


class ProcessStdout(ProcessIO):
    name = 'launch.events.process.ProcessStdout'

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(fd=1, **kwargs)


class ProcessStderr(ProcessIO):
    name = 'launch.events.process.ProcessStderr'

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(fd=2, **kwargs)


class ProcessTargetedEvent(Event):
    name = 'launch.events.process.ProcessTargetedEvent'

    def __init__(self, *, process_matcher: Callable[[Any], bool]) -> None:
        self.process_matcher = process_matcher


class SignalProcess(ProcessTargetedEvent):
    """Sends a signal to the matching processes (to each one's process group)."""

    name = 'launch.events.process.SignalProcess'

    def __init__(self, *, signal_number: int | str, process_matcher: Callable[[Any], bool]
                 ) -> None:
        super().__init__(process_matcher=process_matcher)
        self.signal = (_signal.Signals[signal_number] if isinstance(signal_number, str)
                       else _signal.Signals(signal_number))
        self.signal_name = self.signal.name


class ShutdownProcess(ProcessTargetedEvent):
    """Stops the matching processes as a launch shutdown would."""

    name = 'launch.events.process.ShutdownProcess'


def matches_name(name: str) -> Callable[[Any], bool]:
    return lambda action: action.process_details['name'] == name


def matches_pid(pid: int) -> Callable[[Any], bool]:
    return lambda action: action.process_details.get('pid') == pid


__all__ = ['ProcessExited', 'ProcessIO', 'ProcessStarted', 'ProcessStderr', 'ProcessStdout',
           'ProcessTargetedEvent', 'RunningProcessEvent', 'ShutdownProcess', 'SignalProcess',
           'matches_name', 'matches_pid']

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
