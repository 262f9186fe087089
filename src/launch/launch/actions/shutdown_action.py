"""Shutdown: `<shutdown reason=/>`, shuts the launch down."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.actions.emit_event import EmitEvent
from launch.events.process.process_exited import ProcessExited
from launch.events.shutdown import Shutdown as ShutdownEvent
from launch.frontend.expose import expose_action
from launch.logging import get_logger

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext


@expose_action('shutdown')
class Shutdown(EmitEvent):
    def __init__(self, *, reason: str = 'reason not given', **kwargs: Any) -> None:
        super().__init__(event=ShutdownEvent(reason=reason), **kwargs)

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        reason = entity.get_attr('reason', optional=True)
        if reason:
            kwargs['reason'] = parser.parse_substitution(reason)
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        event = context.get_locals_as_dict().get('event')
        if isinstance(event, ProcessExited):
            get_logger('launch').info(
                f'process[{event.process_name}] was required: shutting down launched system')
        super().execute(context)
