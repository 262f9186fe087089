"""OnStateTransition: entities to run when a LifecycleNode's node makes a transition."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from launch.event import Event
from launch.event_handler import EventHandler

from launch_ros.actions.lifecycle_node import LifecycleNode
from launch_ros.events.lifecycle import StateTransition

if TYPE_CHECKING:
    from launch.some_entities_type import SomeEntitiesType


class OnStateTransition(EventHandler):
    """Matches StateTransition events by node action, transition and states (each None: any);
    a `matcher` given replaces all of them."""

    def __init__(self, *, entities: SomeEntitiesType,
                 target_lifecycle_node: LifecycleNode | None = None,
                 transition: str | None = None, start_state: str | None = None,
                 goal_state: str | None = None,
                 matcher: Callable[[Event], bool] | None = None, **kwargs: Any) -> None:
        if not isinstance(target_lifecycle_node, (LifecycleNode, type(None))):
            raise RuntimeError("OnStateTransition requires a 'LifecycleNode' action as the "
                               'target')
        wanted = {'transition': transition, 'start_state': start_state,
                  'goal_state': goal_state}

        def matches(event: Event) -> bool:
            return (isinstance(event, StateTransition)
                    and target_lifecycle_node in (None, event.action)
                    and all(value is None or getattr(event, key) == value
                            for key, value in wanted.items()))
        super().__init__(matcher=matcher or matches, entities=entities, **kwargs)
        self.__target = target_lifecycle_node

    @property
    def handler_description(self) -> str:
        return '<actions>'

    @property
    def matcher_description(self) -> str:
        # Upstream's text, which names the node action by its id (and nothing else it matches).
        if self.__target is None:
            return 'event == StateTransition'
        return ('event == StateTransition and event.action == '
                f'LifecycleNode({hex(id(self.__target))})')
