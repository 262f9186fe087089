"""BaseEventHandler / EventHandler: entities to run when a matching event happens."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launch.event import Event
    from launch.launch_context import LaunchContext
    from launch.some_entities_type import SomeEntitiesType


class BaseEventHandler:
    def __init__(self, *, matcher: Callable[[Event], bool], handle_once: bool = False) -> None:
        self.__matcher = matcher
        self.__handle_once = handle_once

    @property
    def handle_once(self) -> bool:
        return self.__handle_once

    @property
    def handler_description(self) -> str | None:
        return None

    @property
    def matcher_description(self) -> str | None:
        return None

    def matches(self, event: Event) -> bool:
        return self.__matcher(event)

    def describe(self) -> tuple[str, list[Any]]:
        return (f"{type(self).__name__}(matcher='{self.matcher_description}', "
                f"handler='{self.handler_description}', handle_once={self.handle_once})", [])

    def handle(self, event: Event, context: LaunchContext) -> Any:
        """Puts `event` in the locals; a handle_once handler unregisters itself."""
        context.extend_locals({'event': event})
        if self.handle_once:
            context.unregister_event_handler(self)
        return None


class EventHandler(BaseEventHandler):
    def __init__(self, *, matcher: Callable[[Event], bool],
                 entities: SomeEntitiesType | None = None,
                 handle_once: bool = False) -> None:
        super().__init__(matcher=matcher, handle_once=handle_once)
        self.__entities = entities

    @property
    def entities(self) -> Any:
        return self.__entities

    def describe(self) -> tuple[str, list[Any]]:
        text, entities = super().describe()
        if self.entities:
            entities.extend(self.entities)
        return text, entities

    def handle(self, event: Event, context: LaunchContext) -> Any:
        super().handle(event, context)
        return self.entities
