"""StdoutReadyListener: run actions once a process prints a given text on stdout (e.g. its
"ready" line; a ReadyToTest among the actions starts the tests then)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launch.event_handlers import OnProcessIO


class StdoutReadyListener(OnProcessIO):
    def __init__(self, *, target_action: Any = None, ready_txt: str,
                 actions: Iterable[Any]) -> None:
        self.__ready_txt = ready_txt
        self.__actions = list(actions)
        super().__init__(target_action=target_action, on_stdout=self.__on_stdout)

    def __on_stdout(self, process_io: Any) -> list[Any] | None:
        if self.__ready_txt in process_io.text.decode(errors='replace'):
            return self.__actions
        return None

    def describe(self) -> tuple[str, list[Any]]:
        return f'StdoutReadyListener(ready_txt={self.__ready_txt!r})', list(self.__actions)
