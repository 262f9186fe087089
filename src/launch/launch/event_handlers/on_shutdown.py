"""OnShutdown: run entities (or call a function) when the launch shuts down."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from launch.event import Event
from launch.event_handler import BaseEventHandler
from launch.events.shutdown import Shutdown
from launch.launch_description_entity import LaunchDescriptionEntity
from launch.utilities import is_a_subclass

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_entities_type import SomeEntitiesType


def gen_handler(entities: Any) -> Callable[[Event, LaunchContext], Any]:
    """A callback returning `entities`; its name is what --print shows as the handler."""
    def handler(event: Event, context: LaunchContext) -> Any:
        return entities
    return handler


class OnShutdown(BaseEventHandler):
    def __init__(self, *, on_shutdown: SomeEntitiesType | Callable[[Shutdown, LaunchContext],
                                                          SomeEntitiesType | None],
                 **kwargs: Any) -> None:
        super().__init__(matcher=lambda event: is_a_subclass(event, Shutdown), **kwargs)
        if callable(on_shutdown) and not isinstance(on_shutdown, LaunchDescriptionEntity):
            self.__on_shutdown = on_shutdown
        else:
            self.__on_shutdown = gen_handler(on_shutdown)

    def handle(self, event: Event, context: LaunchContext) -> Any:
        super().handle(event, context)
        return self.__on_shutdown(event, context)

    @property
    def handler_description(self) -> str:
        return f'{self.__on_shutdown}'

    @property
    def matcher_description(self) -> str:
        return 'event issubclass of launch.events.Shutdown'
