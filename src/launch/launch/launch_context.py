"""LaunchContext: the state a launch runs in (configurations, environment, locals, events)."""

from __future__ import annotations

import asyncio
import os
import types
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launch.event import Event
    from launch.event_handler import BaseEventHandler
    from launch.substitution import Substitution


class LaunchContext:
    def __init__(self, *, argv: list[str] | None = None, noninteractive: bool = False) -> None:
        self.argv = list(argv or [])
        self.noninteractive = noninteractive
        self._launch_configurations: dict[str, Any] = {}
        self._configurations_stack: list[dict[str, Any]] = []
        # The children's environment: starts as ours, changed by SetEnvironmentVariable.
        self._environment: dict[str, str] = dict(os.environ)
        self._environment_stack: list[dict[str, str]] = []
        self._locals_stack: list[dict[str, Any]] = [{}]
        self._event_handlers: list[BaseEventHandler] = []
        self._event_queue: asyncio.Queue[Event] | None = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._is_shutdown = False
        # Process groups started by this launch: {pgid: process name}, stopped at the end.
        self._process_groups: dict[int, str] = {}
        self._process_pids: set[int] = set()

    # launch configurations (scoped by GroupAction)
    @property
    def launch_configurations(self) -> dict[str, Any]:
        return self._launch_configurations

    def _push_launch_configurations(self) -> None:
        self._configurations_stack.append(dict(self._launch_configurations))

    def _pop_launch_configurations(self) -> None:
        self._launch_configurations = self._configurations_stack.pop()

    # environment of the processes started from here on
    @property
    def environment(self) -> dict[str, str]:
        return self._environment

    def _push_environment(self) -> None:
        self._environment_stack.append(dict(self._environment))

    def _pop_environment(self) -> None:
        self._environment = self._environment_stack.pop()

    # locals (e.g. `event` in an event handler, the current launch file)
    @property
    def locals(self) -> types.SimpleNamespace:
        return types.SimpleNamespace(**self.get_locals_as_dict())

    def get_locals_as_dict(self) -> dict[str, Any]:
        return dict(self._locals_stack[-1])

    def extend_locals(self, new_locals: dict[str, Any]) -> None:
        self._locals_stack[-1].update(new_locals)

    def _push_locals(self) -> None:
        self._locals_stack.append(dict(self._locals_stack[-1]))

    def _pop_locals(self) -> None:
        self._locals_stack.pop()

    # events
    def register_event_handler(self, handler: BaseEventHandler, append: bool = False) -> None:
        if append:
            self._event_handlers.append(handler)
        else:
            self._event_handlers.insert(0, handler)

    def unregister_event_handler(self, handler: BaseEventHandler) -> None:
        if handler in self._event_handlers:
            self._event_handlers.remove(handler)

    @property
    def event_handlers(self) -> list[BaseEventHandler]:
        return list(self._event_handlers)

    def emit_event_sync(self, event: Event) -> None:
        if self._event_queue is None:
            raise RuntimeError('the launch service is not running')
        self._event_queue.put_nowait(event)

    async def emit_event(self, event: Event) -> None:
        self.emit_event_sync(event)

    @property
    def asyncio_loop(self) -> asyncio.AbstractEventLoop:
        if self._loop is None:
            raise RuntimeError('the launch service is not running')
        return self._loop

    @property
    def is_shutdown(self) -> bool:
        return self._is_shutdown

    def perform_substitution(self, substitution: Substitution) -> str:
        return substitution.perform(self)
