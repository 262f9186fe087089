"""Action: an entity that does something when visited, if its condition holds."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from launch.condition import Condition
    from launch.launch_context import LaunchContext


class Action(LaunchDescriptionEntity):
    def __init__(self, *, condition: Condition | None = None, **unsupported: object) -> None:
        if unsupported:
            # Names what an upstream launch file asked for that this launch does not have.
            raise TypeError(f"{type(self).__name__}: argument '{sorted(unsupported)[0]}' is "
                            'not supported by this launch (see docs/launch.md)')
        self.__condition = condition

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
