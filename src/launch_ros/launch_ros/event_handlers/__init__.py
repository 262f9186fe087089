"""launch_ros.event_handlers: OnStateTransition (a lifecycle node changed state)."""

from launch_ros.event_handlers.on_state_transition import OnStateTransition

__all__ = ['OnStateTransition']
