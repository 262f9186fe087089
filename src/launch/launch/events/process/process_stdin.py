"""ProcessStdin: text on a process's stdin."""

from typing import Any

from launch.events.process.process_io import ProcessIO


class ProcessStdin(ProcessIO):
    name = 'launch.events.process.ProcessStdin'

    def __init__(self, **kwargs: Any) -> None:
        super().__init__(fd=0, **kwargs)
