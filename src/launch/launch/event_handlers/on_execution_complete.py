"""OnExecutionComplete: run entities (or call a function) when an action has completed."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.event_handlers.on_action_event_base import OnActionEventBase
from launch.events.execution_complete import ExecutionComplete

if TYPE_CHECKING:
    from collections.abc import Callable

    from launch.action import Action
    from launch.launch_context import LaunchContext
    from launch.some_entities_type import SomeEntitiesType


class OnExecutionComplete(OnActionEventBase):
    def __init__(self, *, target_action: Callable[[Action], bool] | Action | None = None,
                 on_completion: SomeEntitiesType | Callable[[ExecutionComplete, LaunchContext],
                                                            SomeEntitiesType | None],
                 **kwargs: Any) -> None:
        from launch.action import Action
        super().__init__(action_matcher=target_action, on_event=on_completion,
                         target_event_cls=ExecutionComplete, target_action_cls=Action,
                         **kwargs)
