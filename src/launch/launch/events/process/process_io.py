"""ProcessIO: text a process wrote (or was sent), with the stream it came on."""

from typing import Any

from launch.events.process.running_process_event import RunningProcessEvent


class ProcessIO(RunningProcessEvent):
    name = 'launch.events.process.ProcessIO'

    def __init__(self, *, text: bytes, fd: int, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__text = text
        self.__fd = fd

    @property
    def text(self) -> bytes:
        return self.__text

    @property
    def from_stdin(self) -> bool:
        return self.__fd == 0

    @property
    def from_stdout(self) -> bool:
        return self.__fd == 1

    @property
    def from_stderr(self) -> bool:
        return self.__fd == 2
