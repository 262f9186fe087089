"""StateTransition: a LifecycleNode's node published a transition event."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.event import Event

if TYPE_CHECKING:
    from lifecycle_msgs.msg import TransitionEvent

    from launch_ros.actions.lifecycle_node import LifecycleNode


class StateTransition(Event):
    name = 'launch_ros.events.lifecycle.StateTransition'

    def __init__(self, *, action: LifecycleNode, msg: TransitionEvent) -> None:
        super().__init__()
        self.action = action  # the LifecycleNode action whose node changed state
        self.msg = msg  # the lifecycle_msgs/msg/TransitionEvent
        self.timestamp = msg.timestamp
        self.transition = msg.transition.label
        self.start_state = msg.start_state.label
        self.goal_state = msg.goal_state.label
