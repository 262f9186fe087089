"""OnProcessExit: run entities (or call a function) when a process has exited."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.event_handlers.on_action_event_base import OnActionEventBase
from launch.events.process.process_exited import ProcessExited

if TYPE_CHECKING:
    from collections.abc import Callable

    from launch.actions.execute_local import ExecuteLocal
    from launch.launch_context import LaunchContext
    from launch.some_entities_type import SomeEntitiesType


class OnProcessExit(OnActionEventBase):
    def __init__(self, *,
                 target_action: Callable[[ExecuteLocal], bool] | ExecuteLocal | None = None,
                 on_exit: SomeEntitiesType | Callable[[ProcessExited, LaunchContext],
                                                      SomeEntitiesType | None],
                 **kwargs: Any) -> None:
        from launch.actions.execute_local import ExecuteLocal
        super().__init__(action_matcher=target_action, on_event=on_exit,
                         target_event_cls=ProcessExited, target_action_cls=ExecuteLocal,
                         **kwargs)
