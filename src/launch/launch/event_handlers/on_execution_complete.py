"""OnExecutionComplete: run entities (or call a function) when an action has completed."""

from __future__ import annotations

from typing import Any

from launch.event_handlers.on_action_event_base import OnActionEventBase
from launch.events.execution_complete import ExecutionComplete


class OnExecutionComplete(OnActionEventBase):
    def __init__(self, *, target_action: Any = None, on_completion: Any, **kwargs: Any
                 ) -> None:
        from launch.action import Action
        super().__init__(action_matcher=target_action, on_event=on_completion,
                         target_event_cls=ExecutionComplete, target_action_cls=Action,
                         **kwargs)
