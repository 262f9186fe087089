"""LifecycleTransition: walks lifecycle nodes through a list of transitions, each one
requested (a ChangeState event) once the node has reached the goal of the one before."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any, ClassVar

from launch.action import Action
from launch.actions import EmitEvent, OpaqueFunction, RegisterEventHandler
from launch.event import Event
from launch.event_handler import EventHandler
from launch.logging import get_logger
from launch.some_substitutions_type import SomeSubstitutionsType
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions
from lifecycle_msgs.msg import Transition

from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState, StateTransition, matches_node_name

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext

_SHUTDOWN = {'start_state': 'shuttingdown', 'goal_state': 'finalized'}


class LifecycleTransition(Action):
    # The (transition state, goal state) pair whose StateTransition shows a transition done.
    transition_targets: ClassVar[dict[int, dict[str, str]]] = {
        Transition.TRANSITION_CONFIGURE: {'start_state': 'configuring', 'goal_state': 'inactive'},
        Transition.TRANSITION_CLEANUP: {'start_state': 'cleaningup', 'goal_state': 'unconfigured'},
        Transition.TRANSITION_ACTIVATE: {'start_state': 'activating', 'goal_state': 'active'},
        Transition.TRANSITION_DEACTIVATE: {'start_state': 'deactivating',
                                           'goal_state': 'inactive'},
        Transition.TRANSITION_UNCONFIGURED_SHUTDOWN: _SHUTDOWN,
        Transition.TRANSITION_INACTIVE_SHUTDOWN: _SHUTDOWN,
        Transition.TRANSITION_ACTIVE_SHUTDOWN: _SHUTDOWN,
    }

    def __init__(self, *, lifecycle_node_names: Iterable[SomeSubstitutionsType],
                 transition_ids: Iterable[int | SomeSubstitutionsType], **kwargs: Any) -> None:
        super().__init__(**kwargs)
        names, ids = list(lifecycle_node_names), list(transition_ids)
        if not ids:
            raise ValueError('No transition_ids provided.')
        if not names:
            raise ValueError('No lifecycle_node_names provided.')
        self.__names = [normalize_to_list_of_substitutions(name) for name in names]
        self.__ids = [normalize_to_list_of_substitutions(str(tid) if isinstance(tid, int)
                                                         else tid) for tid in ids]
        self.__handlers: dict[str, list[EventHandler]] = {}
        self.__logger = get_logger(__name__)

    def execute(self, context: LaunchContext) -> list[Action]:
        names = [perform_substitutions(context, name) for name in self.__names]
        ids = []
        for text in (perform_substitutions(context, tid) for tid in self.__ids):
            try:
                ids.append(int(text))
            except ValueError:
                raise ValueError(f'expected integer for lifecycle transition, got {text}'
                                 ) from None
        actions: list[Action] = []
        for name in names:
            emits = [EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_node_name(name),
                                                 transition_id=tid)) for tid in ids]
            handlers = []
            for index, tid in enumerate(ids):
                # Each transition's goal requests the next; the last one's ends the walk.
                then = emits[index + 1] if index + 1 < len(ids) else OpaqueFunction(
                    function=lambda ctx, name=name: self._remove_event_handlers(ctx, name))
                target = self.transition_targets[tid]
                handlers.append(OnStateTransition(
                    matcher=_transition_matcher(name, target['goal_state'],
                                                target['start_state']),
                    entities=[then], handle_once=True))
            # A transition that fails into errorprocessing ends the walk for that node.
            error = EventHandler(
                matcher=_transition_matcher(name, 'errorprocessing'),
                entities=[OpaqueFunction(function=lambda ctx, name=name: self
                                         ._remove_event_handlers(
                                             ctx, name, 'error occured during transitions'))],
                handle_once=True)
            self.__handlers[name] = [*handlers, error]
            context.register_event_handler(error)
            actions += [RegisterEventHandler(event_handler=h) for h in handlers]
            actions.append(emits[0])
        return actions

    def _remove_event_handlers(self, context: LaunchContext, node_name: str,
                               reason: str | None = None) -> None:
        if reason is not None:
            self.__logger.info(f"Stopping transitions for {node_name} because '{reason}'")
        for handler in self.__handlers[node_name]:
            if handler in context.event_handlers:
                context.unregister_event_handler(handler)


def _transition_matcher(node_name: str, goal_state: str,
                        start_state: str | None = None) -> Callable[[Event], bool]:
    full = node_name if node_name.startswith('/') else '/' + node_name
    return lambda event: (isinstance(event, StateTransition)
                          and event.action.node_name == full
                          and event.goal_state == goal_state
                          and (start_state is None or event.start_state == start_state))
