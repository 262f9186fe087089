"""DeclareLaunchArgument: a launch argument, with its default, description and choices."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.frontend.expose import expose_action
from launch.substitution import (
    SomeSubstitutionsType,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext


@expose_action('arg')
class DeclareLaunchArgument(Action):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        choices = [child.get('value', required=True) for child in entity.children_of('choice')]
        kwargs = {'name': entity.get('name', required=True),
                  'default_value': entity.get_substitutions('default'),
                  'description': entity.get('description'), 'choices': choices or None}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, name: str, *, default_value: SomeSubstitutionsType | None = None,
                 description: str | None = None, choices: Iterable[str] | None = None,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__name = name
        self.__default_value = (None if default_value is None
                                else normalize_to_list_of_substitutions(default_value))
        self.__choices = None if choices is None else [str(c) for c in choices]
        if description is None:
            description = ('no description given' if self.__choices is None
                           else f'One of: {self.__choices}')
        self.__description = description
        # Set by LaunchDescription.get_launch_arguments() (shown as `*` by --show-args).
        self._conditionally_included = False

    @property
    def name(self) -> str:
        return self.__name

    @property
    def default_value(self) -> list | None:
        return self.__default_value

    @property
    def description(self) -> str:
        return self.__description

    @property
    def choices(self) -> list[str] | None:
        return self.__choices

    def describe(self) -> str:
        return f"DeclareLaunchArgument('{self.__name}')"

    def execute(self, context: LaunchContext) -> None:
        if self.__name not in context.launch_configurations:
            if self.__default_value is None:
                raise RuntimeError(f"Required launch argument '{self.__name}' (description: "
                                   f"'{self.__description}') was not provided")
            context.launch_configurations[self.__name] = perform_substitutions(
                context, self.__default_value)
        value = context.launch_configurations[self.__name]
        if self.__choices is not None and value not in self.__choices:
            raise RuntimeError(f"Argument '{self.__name}' provided value '{value}' is not "
                               f'valid. Valid options are: {self.__choices}')
        return None
