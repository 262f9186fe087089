"""LaunchDescription: the list of entities a launch file returns."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.launch_description_entity import LaunchDescriptionEntity
from launch.logging import get_logger

if TYPE_CHECKING:
    from launch.actions.declare_launch_argument import DeclareLaunchArgument
    from launch.actions.include_launch_description import IncludeLaunchDescription
    from launch.launch_context import LaunchContext


class LaunchDescription(LaunchDescriptionEntity):
    def __init__(self, initial_entities: Iterable[LaunchDescriptionEntity] | None = None, *,
                 deprecated_reason: str | None = None) -> None:
        self.__entities = list(initial_entities) if initial_entities is not None else []
        self.__deprecated_reason = deprecated_reason

    def describe(self) -> str:
        return f'LaunchDescription({len(self.__entities)} entities)'

    def visit(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        if self.__deprecated_reason is not None:
            path = context.get_locals_as_dict().get('current_launch_file_path')
            if path is not None:
                message = f'launch file [{path}] is deprecated: {self.__deprecated_reason}'
            else:
                message = f'deprecated launch description: {self.__deprecated_reason}'
            get_logger().warning(message)
        return self.__entities

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.__entities

    @property
    def entities(self) -> list[LaunchDescriptionEntity]:
        return self.__entities

    def add_entity(self, entity: LaunchDescriptionEntity) -> None:
        self.__entities.append(entity)

    def add_action(self, action: LaunchDescriptionEntity) -> None:
        self.add_entity(action)

    @property
    def deprecated(self) -> bool:
        return self.__deprecated_reason is not None

    @property
    def deprecated_reason(self) -> str | None:
        return self.__deprecated_reason

    def get_launch_arguments(self, conditional_inclusion: bool = False
                             ) -> list[DeclareLaunchArgument]:
        """The arguments this description declares, those of included descriptions too."""
        return [argument for argument, _ in
                self.get_launch_arguments_with_include_launch_description_actions(
                    conditional_inclusion)]

    def get_launch_arguments_with_include_launch_description_actions(
            self, conditional_inclusion: bool = False,
    ) -> list[tuple[DeclareLaunchArgument, list[IncludeLaunchDescription] | None]]:
        """Each declared argument with the includes it is nested in (None at top level).

        The walk stops at a ResetLaunchConfigurations: arguments after it cannot be set from
        the command line.
        """
        from launch.actions.declare_launch_argument import DeclareLaunchArgument
        from launch.actions.include_launch_description import IncludeLaunchDescription
        from launch.actions.reset_launch_configurations import ResetLaunchConfigurations
        found: list[tuple[DeclareLaunchArgument, list[IncludeLaunchDescription] | None]] = []

        def walk(entities: Iterable[Any], conditional: bool,
                 includes: list[IncludeLaunchDescription] | None) -> None:
            for entity in entities:
                if isinstance(entity, DeclareLaunchArgument):
                    if any(entity.name == known.name for known, _ in found):
                        continue
                    entity._conditionally_included = conditional or entity.condition is not None
                    found.append((entity, includes))
                if isinstance(entity, ResetLaunchConfigurations):
                    return
                inner = includes
                if isinstance(entity, IncludeLaunchDescription):
                    inner = [*(includes or []), entity]
                walk(entity.describe_sub_entities(), False, inner)
                for _, sub_entities in entity.describe_conditional_sub_entities():
                    walk(sub_entities, True, inner)

        walk(self.entities, conditional_inclusion, None)
        return found
