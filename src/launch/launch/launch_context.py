"""LaunchContext: the state a launch runs in (configurations, environment, locals, events).

As upstream, the environment is the launch process's own `os.environ`: actions change it and
the processes started afterwards inherit it; group scopes save and restore it.
"""

from __future__ import annotations

import asyncio
import collections
import os
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from collections.abc import Iterable

    from launch.event import Event
    from launch.event_handler import BaseEventHandler
    from launch.substitution import Substitution


class _ReadOnlyLocals:
    """context.locals: attribute access to the locals, which may not be set this way."""

    def __init__(self, values: dict[str, Any]) -> None:
        object.__setattr__(self, '_values', values)

    def __getattr__(self, key: str) -> Any:
        values = object.__getattribute__(self, '_values')
        if key not in values:
            raise AttributeError(f"context.locals does not contain attribute '{key}', it "
                                 f"contains: [{', '.join(values)}]")
        return values[key]

    def __setattr__(self, key: str, value: Any) -> None:
        raise AttributeError(f"can't set attribute '{key}', locals are read-only")


class LaunchContext:
    def __init__(self, *, argv: Iterable[str] | None = None, noninteractive: bool = False) -> None:
        self.__argv = list(argv) if argv is not None else []
        self.__noninteractive = noninteractive
        self._event_queue: asyncio.Queue = asyncio.Queue()
        self._event_handlers: collections.deque = collections.deque()
        self._completion_futures: list[asyncio.Future] = []
        self.__globals: dict[str, Any] = {}
        self.__locals: dict[str, Any] = {}
        self.__locals_stack: list[dict[str, Any]] = []
        self.__configurations: dict[str, Any] = {}
        self.__configurations_stack: list[dict[str, Any]] = []
        self.__environment_stack: list[dict[str, str]] = []
        self.__environment_at_start = dict(os.environ)
        self.__is_shutdown = False
        self.__loop: asyncio.AbstractEventLoop | None = None
        # Process groups started by this launch: {pgid: process name}, stopped at the end.
        self._process_groups: dict[int, str] = {}
        self._process_pids: set[int] = set()

    @property
    def argv(self) -> list[str]:
        return self.__argv

    @property
    def noninteractive(self) -> bool:
        return self.__noninteractive

    @property
    def is_shutdown(self) -> bool:
        return self.__is_shutdown

    def _set_is_shutdown(self, state: bool) -> None:
        self.__is_shutdown = state

    @property
    def asyncio_loop(self) -> asyncio.AbstractEventLoop | None:
        return self.__loop

    @property
    def _loop(self) -> asyncio.AbstractEventLoop | None:
        """The running loop (the name this workspace's launch_testing uses)."""
        return self.__loop

    def _set_asyncio_loop(self, loop: asyncio.AbstractEventLoop | None) -> None:
        self.__loop = loop

    def add_completion_future(self, completion_future: asyncio.Future) -> None:
        """A future the launch waits for before it counts as idle."""
        self._completion_futures.append(completion_future)

    # -- locals (e.g. `event` in an event handler, the current launch file) ----------------
    def extend_globals(self, extensions: dict[str, Any]) -> None:
        self.__globals.update(extensions)

    def extend_locals(self, extensions: dict[str, Any]) -> None:
        self.__locals.update(extensions)

    def get_locals_as_dict(self) -> dict[str, Any]:
        return {**self.__globals, **self.__locals}

    @property
    def locals(self) -> _ReadOnlyLocals:
        return _ReadOnlyLocals(self.get_locals_as_dict())

    def _push_locals(self) -> None:
        self.__locals_stack.append(dict(self.__locals))

    def _pop_locals(self) -> None:
        if not self.__locals_stack:
            raise RuntimeError('locals stack unexpectedly empty')
        self.__locals = self.__locals_stack.pop()

    # -- launch configurations (scoped by GroupAction) --------------------------------------
    @property
    def launch_configurations(self) -> dict[str, Any]:
        return self.__configurations

    def _push_launch_configurations(self) -> None:
        self.__configurations_stack.append(dict(self.__configurations))

    def _pop_launch_configurations(self) -> None:
        if not self.__configurations_stack:
            raise RuntimeError('launch_configurations stack unexpectedly empty')
        self.__configurations = self.__configurations_stack.pop()

    # -- environment of the processes started from here on ---------------------------------
    @property
    def environment(self) -> os._Environ:
        return os.environ

    def _push_environment(self) -> None:
        self.__environment_stack.append(dict(os.environ))

    def _pop_environment(self) -> None:
        if not self.__environment_stack:
            raise RuntimeError('environment stack unexpectedly empty')
        _replace_environment(self.__environment_stack.pop())

    def _reset_environment(self) -> None:
        _replace_environment(self.__environment_at_start)

    # -- events ----------------------------------------------------------------------------
    def would_handle_event(self, event: Event) -> bool:
        return any(handler.matches(event) for handler in self._event_handlers)

    def register_event_handler(self, event_handler: BaseEventHandler,
                               append: bool = False) -> None:
        """Newest first (upstream): a later handler sees an event before earlier ones."""
        if append:
            self._event_handlers.append(event_handler)
        else:
            self._event_handlers.appendleft(event_handler)

    def unregister_event_handler(self, event_handler: BaseEventHandler) -> None:
        self._event_handlers.remove(event_handler)

    @property
    def event_handlers(self) -> list[BaseEventHandler]:
        return list(self._event_handlers)

    def emit_event_sync(self, event: Event) -> None:
        self._event_queue.put_nowait(event)

    async def emit_event(self, event: Event) -> None:
        await self._event_queue.put(event)

    def perform_substitution(self, substitution: Substitution) -> str:
        return substitution.perform(self)


def _replace_environment(values: dict[str, str]) -> None:
    # os.environ must stay the same object (children and putenv use it): change it in place.
    os.environ.clear()
    os.environ.update(values)
