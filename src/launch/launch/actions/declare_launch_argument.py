"""DeclareLaunchArgument: `<arg name= default= description=>`, a launch argument.

Its description lists the allowed choices; a value outside them is an error naming the
argument, the value and the choices.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action
from launch.logging import get_logger
from launch.substitution import Substitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


def _fail(message: str) -> RuntimeError:
    get_logger(__name__).error(message)
    return RuntimeError(message)


@expose_action('arg')
class DeclareLaunchArgument(Action):
    def __init__(self, name: str, *, default_value: SomeSubstitutionsType | None = None,
                 description: str | None = None,
                 choices: list[str] | None = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__name = name
        self.__default_value = (None if default_value is None
                                else normalize_to_list_of_substitutions(default_value))
        if choices is not None:
            if len(choices) == 0:
                raise _fail('Provided choices arg is empty. Use None to ignore the choice list.')
            if (default_value is not None and not isinstance(default_value, (Substitution, list))
                    and default_value not in choices):
                raise _fail(f'Provided default_value "{default_value}" is not in provided '
                            f'choices "{choices}".')
        if description is None:
            description = ('no description given' if choices is None
                           else f'One of: {choices}')
        elif choices is not None:
            description += ('' if description.endswith('.') else '.') + \
                f' Valid choices are: {choices}'
        self.__description = description
        self.__choices = choices
        # Set by LaunchDescription.get_launch_arguments(): may this argument be skipped?
        self._conditionally_included = False

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs['name'] = parser.escape_characters(entity.get_attr('name'))
        default = entity.get_attr('default', optional=True)
        if default is not None:
            kwargs['default_value'] = parser.parse_substitution(default)
        description = entity.get_attr('description', optional=True)
        if description is not None:
            kwargs['description'] = parser.escape_characters(description)
        choices = entity.get_attr('choice', data_type=list[Entity], optional=True)
        if choices is not None:
            kwargs['choices'] = [parser.escape_characters(choice.get_attr('value'))
                                 for choice in choices]
        return cls, kwargs

    @property
    def name(self) -> str:
        return self.__name

    @property
    def default_value(self) -> list[Substitution] | None:
        return self.__default_value

    @property
    def description(self) -> str:
        return self.__description

    @property
    def choices(self) -> list[str] | None:
        return self.__choices

    def execute(self, context: LaunchContext) -> None:
        if self.name not in context.launch_configurations:
            if self.default_value is None:
                get_logger(__name__).error(
                    f'Required launch argument "{self.name}" (description: '
                    f'"{self.description}") was not provided')
                raise RuntimeError(f'Required launch argument "{self.name}" was not provided.')
            context.launch_configurations[self.name] = perform_substitutions(
                context, self.default_value)
        value = context.launch_configurations[self.name]
        if self.__choices is not None and value not in self.__choices:
            raise _fail(f'Argument "{self.name}" provided value "{value}" is not valid. Valid '
                        f'options are: {self.__choices}')
