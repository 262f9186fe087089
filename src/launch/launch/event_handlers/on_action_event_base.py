"""OnActionEventBase: run entities (or call a function) on an event about some action.

The action is given as an instance (that action only), a predicate of the action, or None
(any action).
"""

from __future__ import annotations

import collections.abc
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from launch.event import Event
from launch.event_handler import BaseEventHandler
from launch.launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from launch.action import Action
    from launch.launch_context import LaunchContext
    from launch.some_entities_type import SomeEntitiesType


class OnActionEventBase(BaseEventHandler):
    def __init__(self, *, action_matcher: Callable[[Action], bool] | Action | None,
                 on_event: SomeEntitiesType | Callable[[Event, LaunchContext],
                                                       SomeEntitiesType | None],
                 target_event_cls: type[Event], target_action_cls: type[Action],
                 **kwargs: Any) -> None:
        if not issubclass(target_event_cls, Event):
            raise TypeError("'target_event_cls' must be a subclass of 'Event'")
        if not (action_matcher is None or isinstance(action_matcher, target_action_cls)
                or callable(action_matcher)):
            raise TypeError(f"action_matcher must be an '{target_action_cls.__name__}' "
                            'instance or a callable')
        self.__target_action_cls = target_action_cls
        self.__target_event_cls = target_event_cls
        self.__action_matcher = action_matcher

        def matcher(event: Event) -> bool:
            if not isinstance(event, target_event_cls):
                return False
            if action_matcher is None:
                return True
            if callable(action_matcher):
                return action_matcher(event.action)
            return event.action is action_matcher

        super().__init__(matcher=matcher, **kwargs)
        self.__entities: list[LaunchDescriptionEntity] = []
        self.__on_event: Callable[[Event, LaunchContext], Any] | None = None
        if callable(on_event) and not isinstance(on_event, LaunchDescriptionEntity):
            self.__on_event = on_event
        elif isinstance(on_event, collections.abc.Iterable):
            for entity in on_event:
                if not isinstance(entity, LaunchDescriptionEntity):
                    raise TypeError("expected all items in 'on_event' iterable to be of type "
                                    f"'LaunchDescriptionEntity' but got '{type(entity)}'")
            self.__entities = list(on_event)
        else:
            self.__entities = [on_event]

    def handle(self, event: Event, context: LaunchContext) -> Any:
        super().handle(event, context)
        if self.__entities:
            return self.__entities
        return None if self.__on_event is None else self.__on_event(event, context)

    def describe(self) -> tuple[str, list[Any]]:
        text, entities = super().describe()
        entities.extend(self.__entities)
        return text, entities

    @property
    def handler_description(self) -> str:
        return '<actions>' if self.__entities else f'{self.__on_event}'

    @property
    def matcher_description(self) -> str:
        event_name = self.__target_event_cls.__name__
        if self.__action_matcher is None:
            return f'event == {event_name}'
        return f'event == {event_name} and {self.__target_action_cls.__name__}(event.action)'
