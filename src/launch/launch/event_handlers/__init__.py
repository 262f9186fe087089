"""launch.event_handlers: run entities when a process starts, prints, exits, or at shutdown."""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from launch._missing import module_getattr
from launch.event import Event
from launch.event_handler import BaseEventHandler, EventHandler
from launch.events import ExecutionComplete, Shutdown
from launch.events.process import ProcessExited, ProcessIO, ProcessStarted

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


def _as_list(entities: Any) -> list[Any]:
    if entities is None:
        return []
    return list(entities) if isinstance(entities, (list, tuple)) else [entities]


class _OnActionEvent(BaseEventHandler):
    """Matches `event_type` events of `target_action` (an action, a predicate, or any)."""

    event_type: type = Event

    def __init__(self, *, target_action: Any = None, on_event: Any = None,
                 handle_once: bool = False) -> None:
        def matcher(event: Event) -> bool:
            if not isinstance(event, self.event_type):
                return False
            action = getattr(event, 'action', None)
            if target_action is None:
                return True
            if callable(target_action) and not hasattr(target_action, 'visit'):
                return bool(target_action(action))
            return action is target_action
        super().__init__(matcher=matcher, handle_once=handle_once)
        self.target_action = target_action
        self.on_event = on_event

    def handle(self, event: Event, context: LaunchContext) -> Any:
        super().handle(event, context)
        if callable(self.on_event) and not hasattr(self.on_event, 'visit'):
            return self.on_event(event, context)
        return self.on_event

    def describe(self) -> tuple[str, list[Any]]:
        entities = [] if callable(self.on_event) else _as_list(self.on_event)
        return f'{type(self).__name__}(...)', entities


class OnProcessStart(_OnActionEvent):
    event_type = ProcessStarted

    def __init__(self, *, target_action: Any = None, on_start: Any = None,
                 handle_once: bool = False) -> None:
        super().__init__(target_action=target_action, on_event=on_start,
                         handle_once=handle_once)


class OnProcessExit(_OnActionEvent):
    event_type = ProcessExited

    def __init__(self, *, target_action: Any = None, on_exit: Any = None,
                 handle_once: bool = False) -> None:
        super().__init__(target_action=target_action, on_event=on_exit,
                         handle_once=handle_once)


class OnExecutionComplete(_OnActionEvent):
    event_type = ExecutionComplete

    def __init__(self, *, target_action: Any = None, on_completion: Any = None,
                 handle_once: bool = False) -> None:
        super().__init__(target_action=target_action, on_event=on_completion,
                         handle_once=handle_once)


class OnProcessIO(_OnActionEvent):
    """Calls on_stdout / on_stderr (functions of the event) with each chunk a process writes."""

    event_type = ProcessIO

    def __init__(self, *, target_action: Any = None,
                 on_stdin: Callable[[ProcessIO], Any] | None = None,
                 on_stdout: Callable[[ProcessIO], Any] | None = None,
                 on_stderr: Callable[[ProcessIO], Any] | None = None) -> None:
        def dispatch(event: ProcessIO, context: LaunchContext) -> Any:
            callback = on_stdout if event.from_stdout else on_stderr
            return None if callback is None else callback(event)
        super().__init__(target_action=target_action, on_event=dispatch)


class OnShutdown(BaseEventHandler):
    def __init__(self, *, on_shutdown: Any, handle_once: bool = False) -> None:
        super().__init__(matcher=lambda event: isinstance(event, Shutdown),
                         handle_once=handle_once)
        self.on_shutdown = on_shutdown

    def handle(self, event: Event, context: LaunchContext) -> Any:
        super().handle(event, context)
        if callable(self.on_shutdown) and not hasattr(self.on_shutdown, 'visit'):
            return self.on_shutdown(event, context)
        return self.on_shutdown

    def describe(self) -> tuple[str, list[Any]]:
        entities = [] if callable(self.on_shutdown) else _as_list(self.on_shutdown)
        return 'OnShutdown(...)', entities


def event_named(name: str) -> Callable[[Event], bool]:
    return lambda event: event.name == name


__all__ = ['EventHandler', 'OnExecutionComplete', 'OnProcessExit', 'OnProcessIO',
           'OnProcessStart', 'OnShutdown', 'event_named']

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
