"""OnProcessIO: call on_stdin / on_stdout / on_stderr with each chunk of a process's I/O."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from launch.event_handlers.on_action_event_base import OnActionEventBase
from launch.events.process.process_io import ProcessIO
from launch.some_entities_type import SomeEntitiesType

if TYPE_CHECKING:
    from launch.action import Action
    from launch.launch_context import LaunchContext

IOCallback = Callable[[ProcessIO], SomeEntitiesType | None]


class OnProcessIO(OnActionEventBase):
    def __init__(self, *, target_action: Callable[[Action], bool] | Action | None = None,
                 on_stdin: IOCallback | None = None,
                 on_stdout: IOCallback | None = None, on_stderr: IOCallback | None = None,
                 **kwargs: Any) -> None:
        from launch.actions.execute_local import ExecuteLocal

        # Named `handle`, as upstream's: --print shows the function's name.
        def handle(event: ProcessIO, context: LaunchContext) -> Any:
            for wanted, callback in ((event.from_stdout, on_stdout),
                                     (event.from_stderr, on_stderr),
                                     (event.from_stdin, on_stdin)):
                if wanted and callback is not None:
                    return callback(event)
            return None

        super().__init__(action_matcher=target_action, on_event=handle,
                         target_event_cls=ProcessIO, target_action_cls=ExecuteLocal, **kwargs)
