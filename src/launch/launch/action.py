"""Action: an entity that does something when visited, if its condition holds."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from launch.condition import Condition
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext


class Action(LaunchDescriptionEntity):
    def __init__(self, *, condition: Condition | None = None) -> None:
        self.__condition = condition

    @staticmethod
    def parse(entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        """A front-end tag's `if` / `unless` as a `condition` keyword argument."""
        from launch.conditions import IfCondition, UnlessCondition
        if_text = entity.get_attr('if', optional=True)
        unless_text = entity.get_attr('unless', optional=True)
        if if_text is not None and unless_text is not None:
            raise RuntimeError("if and unless conditions can't be used simultaneously")
        kwargs: dict[str, Any] = {}
        if if_text is not None:
            kwargs['condition'] = IfCondition(predicate_expression=parser.parse_substitution(
                if_text))
        if unless_text is not None:
            kwargs['condition'] = UnlessCondition(
                predicate_expression=parser.parse_substitution(unless_text))
        return Action, kwargs

    @property
    def condition(self) -> Condition | None:
        return self.__condition

    def describe(self) -> str:
        return repr(self)

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return []

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.get_sub_entities() if self.condition is None else []

    def describe_conditional_sub_entities(
            self) -> list[tuple[str, Iterable[LaunchDescriptionEntity]]]:
        if self.condition is None:
            return []
        return [(f'Conditionally included by {self.describe()}', self.get_sub_entities())]

    def visit(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        if self.__condition is not None and not self.__condition.evaluate(context):
            return None
        try:
            return self.execute(context)
        finally:
            self.__announce_completion(context)

    def __announce_completion(self, context: LaunchContext) -> None:
        # ExecutionComplete only when someone listens; an action with a future completes
        # when its future does, and a handler registered meanwhile hears of it too.
        from launch.events.execution_complete import ExecutionComplete
        event = ExecutionComplete(action=self)
        future = self.get_asyncio_future()
        if future is None:
            if context.would_handle_event(event):
                context.emit_event_sync(event)
            return

        def completed(_: object) -> None:
            if context.would_handle_event(event):
                context.emit_event_sync(event)
        future.add_done_callback(completed)

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        return None
