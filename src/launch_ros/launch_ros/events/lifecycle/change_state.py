"""ChangeState: asks the LifecycleNode actions its matcher selects to make a transition."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, ClassVar

from launch.event import Event
from lifecycle_msgs.msg import State, Transition

if TYPE_CHECKING:
    from launch_ros.actions.lifecycle_node import LifecycleNode

# The transitions a user may request (lifecycle_msgs' others are internal results).
_TRANSITIONS = ('CREATE', 'CONFIGURE', 'CLEANUP', 'ACTIVATE', 'DEACTIVATE',
                'UNCONFIGURED_SHUTDOWN', 'INACTIVE_SHUTDOWN', 'ACTIVE_SHUTDOWN', 'DESTROY')
_STATES = ('PRIMARY_STATE_UNKNOWN', 'PRIMARY_STATE_UNCONFIGURED', 'PRIMARY_STATE_INACTIVE',
           'PRIMARY_STATE_ACTIVE', 'PRIMARY_STATE_FINALIZED', 'TRANSITION_STATE_CONFIGURING',
           'TRANSITION_STATE_CLEANINGUP', 'TRANSITION_STATE_SHUTTINGDOWN',
           'TRANSITION_STATE_ACTIVATING', 'TRANSITION_STATE_DEACTIVATING',
           'TRANSITION_STATE_ERRORPROCESSING')


class ChangeState(Event):
    name = 'launch_ros.events.lifecycle.ChangeState'
    valid_transitions: ClassVar[dict[int, str]] = {
        getattr(Transition, f'TRANSITION_{name}'): f'TRANSITION_{name}' for name in _TRANSITIONS}
    valid_states: ClassVar[dict[int, str]] = {getattr(State, name): name for name in _STATES}

    def __init__(self, *, lifecycle_node_matcher: Callable[[LifecycleNode], bool],
                 transition_id: int) -> None:
        super().__init__()
        if transition_id not in self.valid_transitions:
            allowed = ', '.join(f'{label}: {tid}' for tid, label in
                                self.valid_transitions.items())
            raise ValueError(f"given transition_id of '{transition_id}', expected one of "
                             f'{{{allowed}}}')
        self.lifecycle_node_matcher = lifecycle_node_matcher
        self.transition_id = transition_id
