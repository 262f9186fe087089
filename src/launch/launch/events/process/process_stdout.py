"""ProcessStdout: text on a process's stdout."""

from typing import Any

from launch.events.process.process_io import ProcessIO


class ProcessStdout(ProcessIO):
    name = 'launch.events.process.ProcessStdout'

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(fd=1, **kwargs)
