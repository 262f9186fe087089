"""Action: an entity that does something when visited, if its condition holds."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from launch.condition import Condition
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext


class Action(LaunchDescriptionEntity):
    def __init__(self, *, condition: Condition | None = None, **unsupported: object) -> None:
        if unsupported:
            # Names what an upstream launch file asked for that this launch does not have.
            raise TypeError(f"{type(self).__name__}: argument '{sorted(unsupported)[0]}' is "
                            'not supported by this launch (see docs/launch.md)')
        self.__condition = condition

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        """A front-end tag as (the class to build, its keyword arguments): upstream's hook,
        which an action exposed with launch.frontend.expose_action overrides."""
        return cls, cls.parse_condition(entity)

    @staticmethod
    def parse_condition(entity: Entity) -> dict[str, Any]:
        """The `if` / `unless` attributes every action tag takes, as a `condition` argument."""
        from launch.conditions import IfCondition, UnlessCondition
        from launch.frontend.entity import FrontendError
        from launch.frontend.parse_substitution import parse_substitutions
        if_text, unless_text = entity.get('if'), entity.get('unless')
        if if_text is not None and unless_text is not None:
            raise FrontendError(f"<{entity.tag}> cannot have both 'if' and 'unless'")
        if if_text is not None:
            return {'condition': IfCondition(parse_substitutions(if_text))}
        if unless_text is not None:
            return {'condition': UnlessCondition(parse_substitutions(unless_text))}
        return {}

    @property
    def condition(self) -> Condition | None:
        return self.__condition

    def visit(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        if self.__condition is None or self.__condition.evaluate(context):
            return self.execute(context)
        return None

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        return None

    def describe(self) -> str:
        return f'{type(self).__name__}'
