"""IncludeLaunchDescription: another launch file, with launch arguments given to it."""

from __future__ import annotations

import os
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.actions.simple import SetLaunchConfiguration
from launch.frontend.expose import expose_action
from launch.launch_description_entity import LaunchDescriptionEntity
from launch.substitution import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext


class _Locals(LaunchDescriptionEntity):
    """Pushes (with values) or pops the context's locals around an included file."""

    def __init__(self, values: dict[str, Any] | None) -> None:
        self.values = values

    def visit(self, context: LaunchContext) -> None:
        if self.values is None:
            context._pop_locals()
        else:
            context._push_locals()
            context.extend_locals(self.values)
        return None


@expose_action('include')
class IncludeLaunchDescription(Action):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        from launch.frontend.entity import FrontendError
        from launch.launch_description_sources import AnyLaunchDescriptionSource
        arguments = []
        for child in entity.children:
            if child.tag != 'arg':
                raise FrontendError(f'<include> holds <arg> elements only, got <{child.tag}>')
            arguments.append((child.get('name', required=True),
                              child.get_substitutions('value', required=True)))
            child.check_all_used()
        source = AnyLaunchDescriptionSource(entity.get_substitutions('file', True))
        kwargs = {'launch_description_source': source, 'launch_arguments': arguments}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, launch_description_source: Any, *,
                 launch_arguments: Iterable[tuple[Any, Any]] | dict | None = None,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        from launch.launch_description import LaunchDescription
        from launch.launch_description_sources import LaunchDescriptionSource
        if isinstance(launch_description_source, LaunchDescription):
            launch_description_source = LaunchDescriptionSource(launch_description_source)
        self.launch_description_source = launch_description_source
        if isinstance(launch_arguments, dict):
            launch_arguments = launch_arguments.items()
        self.launch_arguments = [(normalize_to_list_of_substitutions(k),
                                  normalize_to_list_of_substitutions(v))
                                 for k, v in (launch_arguments or [])]

    def describe(self) -> str:
        return f'IncludeLaunchDescription({self.launch_description_source.location})'

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        description = self.launch_description_source.get_launch_description(context)
        location = self.launch_description_source.location
        given = [(perform_substitutions(context, k), perform_substitutions(context, v))
                 for k, v in self.launch_arguments]
        names = {name for name, _ in given}
        for argument in description.get_launch_arguments():
            if argument._conditionally_included or argument.default_value is not None:
                continue
            if argument.name not in names and argument.name not in context.launch_configurations:
                raise RuntimeError(
                    f"Included launch description missing required argument '{argument.name}' "
                    f"(description: '{argument.description}'), given: "
                    f"[{', '.join(name for name, _ in given)}]")
        settings = [SetLaunchConfiguration(name, value) for name, value in given]
        file_locals = None
        if os.path.isfile(location):
            path = os.path.abspath(location)
            file_locals = {'current_launch_file_path': path,
                           'current_launch_file_directory': os.path.dirname(path)}
        if file_locals is None:
            return [*settings, description]
        return [*settings, _Locals(file_locals), description, _Locals(None)]
