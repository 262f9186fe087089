"""IncludeLaunchDescription: `<include file=>`, another launch file (or description).

Its launch arguments become launch configurations before the included entities run; a
required argument that nobody gives is an error naming it, before anything starts.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.actions.set_launch_configuration import SetLaunchConfiguration
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext
from launch.launch_description_source import LaunchDescriptionSource
from launch.launch_description_sources.any_launch_description_source import (
    AnyLaunchDescriptionSource,
)
from launch.logging import get_logger
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.frontend.parser import Parser
    from launch.launch_description_entity import LaunchDescriptionEntity
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_action('include')
class IncludeLaunchDescription(Action):
    def __init__(self,
                 launch_description_source: LaunchDescriptionSource | SomeSubstitutionsType, *,
                 launch_arguments: Iterable[tuple[SomeSubstitutionsType, SomeSubstitutionsType]]
                 | None = None,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        if not isinstance(launch_description_source, LaunchDescriptionSource):
            launch_description_source = AnyLaunchDescriptionSource(launch_description_source)
        self.__source = launch_description_source
        self.__launch_arguments = tuple(launch_arguments) if launch_arguments else ()

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs['launch_description_source'] = parser.parse_substitution(entity.get_attr('file'))
        args = entity.get_attr('arg', data_type=list[Entity], optional=True)
        if args is not None:
            kwargs['launch_arguments'] = [
                (parser.parse_substitution(arg.get_attr('name')),
                 parser.parse_substitution(arg.get_attr('value'))) for arg in args]
            for arg in args:
                arg.assert_entity_completely_parsed()
        return cls, kwargs

    @property
    def launch_description_source(self) -> LaunchDescriptionSource:
        return self.__source

    @property
    def launch_arguments(self) -> Sequence[tuple[Any, Any]]:
        return self.__launch_arguments

    def _get_launch_file(self) -> str:
        return os.path.abspath(self.__source.location)

    def _get_launch_file_directory(self) -> str:
        path = self._get_launch_file()
        # A description given in a script has no file: its location ('<script>') is passed on.
        return os.path.dirname(path) if os.path.exists(path) else self.__source.location

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        description = self.__source.try_get_launch_description_without_context()
        return [description] if description is not None else []

    def _argument_names(self, context: LaunchContext) -> list[str]:
        return [perform_substitutions(context, normalize_to_list_of_substitutions(name))
                for name, _ in self.__launch_arguments]

    def _try_get_arguments_names_without_context(self) -> list[str]:
        try:
            return self._argument_names(LaunchContext())
        except Exception as error:
            get_logger(__name__).debug(f'Failed to get launch arguments names for launch '
                                       f"description '{self.__source.location}', with "
                                       f'exception: {error}')
            return []

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        description = self.__source.get_launch_description(context)
        context.extend_locals({'current_launch_file_path': self._get_launch_file(),
                               'current_launch_file_directory':
                                   self._get_launch_file_directory()})
        given = self._argument_names(context)
        for argument, includes in (
                description.get_launch_arguments_with_include_launch_description_actions()):
            if argument._conditionally_included or argument.default_value is not None:
                continue
            names = list(given)
            for include in includes or []:
                names.extend(include._try_get_arguments_names_without_context())
            if argument.name not in names:
                raise RuntimeError(f"Included launch description missing required argument "
                                   f"'{argument.name}' (description: "
                                   f"'{argument.description}'), given: [{', '.join(names)}]")
        settings = [SetLaunchConfiguration(name, value)
                    for name, value in self.__launch_arguments]
        return [*settings, description]
