"""ProcessStderr: text on a process's stderr."""

from typing import Any

from launch.events.process.process_io import ProcessIO


class ProcessStderr(ProcessIO):
    name = 'launch.events.process.ProcessStderr'

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(fd=2, **kwargs)
