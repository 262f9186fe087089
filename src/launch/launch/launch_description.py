"""LaunchDescription: the list of entities a launch file returns."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.launch_description_entity import LaunchDescriptionEntity

if TYPE_CHECKING:
    from launch.actions.declare_launch_argument import DeclareLaunchArgument
    from launch.launch_context import LaunchContext


class LaunchDescription(LaunchDescriptionEntity):
    def __init__(self, initial_entities: Iterable[LaunchDescriptionEntity] | None = None, *,
                 deprecated_reason: str | None = None) -> None:
        self.__entities = list(initial_entities or [])
        for entity in self.__entities:
            _check_entity(entity)
        self.deprecated_reason = deprecated_reason

    @property
    def entities(self) -> list[LaunchDescriptionEntity]:
        return self.__entities

    def add_entity(self, entity: LaunchDescriptionEntity) -> None:
        _check_entity(entity)
        self.__entities.append(entity)

    def add_action(self, action: LaunchDescriptionEntity) -> None:
        self.add_entity(action)

    def visit(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        return list(self.__entities)

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return list(self.__entities)

    def get_launch_arguments(self, conditional_inclusion: bool = False
                             ) -> list[DeclareLaunchArgument]:
        """The arguments this description declares (not those of the files it includes)."""
        from launch.actions.declare_launch_argument import DeclareLaunchArgument
        from launch.actions.include_launch_description import IncludeLaunchDescription
        found: list[DeclareLaunchArgument] = []
        names: set[str] = set()

        def walk(entities: list[Any], conditional: bool) -> None:
            for entity in entities:
                if isinstance(entity, DeclareLaunchArgument):
                    entity._conditionally_included = conditional or entity.condition is not None
                    if entity.name not in names:
                        names.add(entity.name)
                        found.append(entity)
                    continue
                if isinstance(entity, IncludeLaunchDescription):
                    continue
                if not isinstance(entity, LaunchDescriptionEntity):
                    continue
                inner = conditional or getattr(entity, 'condition', None) is not None
                walk(entity.describe_sub_entities(), inner)
                for _, sub in entity.describe_conditional_sub_entities():
                    walk(list(sub), True)

        walk(self.__entities, conditional_inclusion)
        return found


def _check_entity(entity: Any) -> None:
    if not isinstance(entity, LaunchDescriptionEntity):
        raise TypeError(f'LaunchDescription holds actions, got {type(entity).__name__}: '
                        f'{entity!r}')
