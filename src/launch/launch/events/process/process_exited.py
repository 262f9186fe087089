"""ProcessExited: a process has ended, with its return code."""

from typing import Any

from launch.events.process.running_process_event import RunningProcessEvent


class ProcessExited(RunningProcessEvent):
    name = 'launch.events.process.ProcessExited'

    def __init__(self, *, returncode: int, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__returncode = returncode

    @property
    def returncode(self) -> int:
        return self.__returncode
