"""EventHandler: entities to run when a matching event happens."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from launch.event import Event

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class BaseEventHandler:
    def __init__(self, *, matcher: Callable[[Event], bool], handle_once: bool = False) -> None:
        self.matcher = matcher
        self.handle_once = handle_once

    def matches(self, event: Event) -> bool:
        return bool(self.matcher(event))

    def describe(self) -> tuple[str, list[Any]]:
        return f'{type(self).__name__}(matcher=...)', []

    def handle(self, event: Event, context: LaunchContext) -> Any:
        context.extend_locals({'event': event})
        if self.handle_once:
            context.unregister_event_handler(self)
        return None


class EventHandler(BaseEventHandler):
    def __init__(self, *, matcher: Callable[[Event], bool], entities: Any = None,
                 handle_once: bool = False) -> None:
        super().__init__(matcher=matcher, handle_once=handle_once)
        self.entities = entities

    def describe(self) -> tuple[str, list[Any]]:
        entities = self.entities if isinstance(self.entities, list) else (
            [] if self.entities is None else [self.entities])
        return f'{type(self).__name__}(matcher=...)', entities

    def handle(self, event: Event, context: LaunchContext) -> Any:
        super().handle(event, context)
        return self.entities
