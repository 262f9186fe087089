"""OpaqueCoroutine: runs coroutine(context, *args, **kwargs) on the launch loop.

The launch waits for it before it is idle; a shutdown cancels it.
"""

from __future__ import annotations

import asyncio
import collections.abc
from collections.abc import Awaitable, Callable, Iterable
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.event_handlers.on_shutdown import OnShutdown
from launch.utilities import ensure_argument_type

if TYPE_CHECKING:
    from launch.event import Event
    from launch.launch_context import LaunchContext


class OpaqueCoroutine(Action):
    def __init__(self, *, coroutine: Callable[..., Awaitable[None]],
                 args: Iterable[Any] | None = None, kwargs: dict[str, Any] | None = None,
                 ignore_context: bool = False, **left_over_kwargs: Any) -> None:
        super().__init__(**left_over_kwargs)
        if not asyncio.iscoroutinefunction(coroutine):
            raise TypeError("OpaqueCoroutine expected a coroutine function for 'coroutine', "
                            f"got '{type(coroutine)}'")
        ensure_argument_type(args, (collections.abc.Iterable, type(None)), 'args',
                             'OpaqueCoroutine')
        ensure_argument_type(kwargs, (dict, type(None)), 'kwargs', 'OpaqueCoroutine')
        ensure_argument_type(ignore_context, bool, 'ignore_context', 'OpaqueCoroutine')
        self.__coroutine = coroutine
        self.__args = list(args) if args is not None else []
        self.__kwargs = dict(kwargs) if kwargs is not None else {}
        self.__ignore_context = ignore_context
        self.__future: asyncio.Future | None = None

    def __on_shutdown(self, event: Event, context: LaunchContext) -> None:
        if self.__future is not None:
            self.__future.cancel()

    def execute(self, context: LaunchContext) -> None:
        args = self.__args if self.__ignore_context else [context, *self.__args]
        self.__future = context.asyncio_loop.create_task(
            self.__coroutine(*args, **self.__kwargs))
        context.register_event_handler(OnShutdown(on_shutdown=self.__on_shutdown))

    def get_asyncio_future(self) -> asyncio.Future | None:
        return self.__future
