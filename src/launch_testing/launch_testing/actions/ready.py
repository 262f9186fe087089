"""ReadyToTest: tells the test runner that the active tests may start."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from launch import Action, logging

if TYPE_CHECKING:
    from launch import LaunchContext


class ReadyToTest(Action):
    def __init__(self) -> None:
        super().__init__()
        self._callbacks: list[Callable[[], None]] = []

    def _add_callback(self, callback: Callable[[], None]) -> None:
        self._callbacks.append(callback)

    def execute(self, context: LaunchContext) -> None:
        for callback in self._callbacks:
            try:
                callback()
            except Exception as error:  # a broken callback must not stop the launch
                logging.get_logger('launch_testing').error(f'ReadyToTest callback: {error}')
        return None
