"""OnProcessStart: run entities (or call a function) when a process has started."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.event_handlers.on_action_event_base import OnActionEventBase
from launch.events.process.process_started import ProcessStarted

if TYPE_CHECKING:
    from collections.abc import Callable

    from launch.action import Action
    from launch.launch_context import LaunchContext
    from launch.some_entities_type import SomeEntitiesType


class OnProcessStart(OnActionEventBase):
    def __init__(self, *, target_action: Callable[[Action], bool] | Action | None = None,
                 on_start: SomeEntitiesType | Callable[[ProcessStarted, LaunchContext],
                                                       SomeEntitiesType | None],
                 **kwargs: Any) -> None:
        # ExecuteProcess, as upstream (its matcher reads '... and ExecuteProcess(event.action)').
        from launch.actions.execute_process import ExecuteProcess
        super().__init__(action_matcher=target_action, on_event=on_start,
                         target_event_cls=ProcessStarted, target_action_cls=ExecuteProcess,
                         **kwargs)
