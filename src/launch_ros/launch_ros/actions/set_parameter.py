"""SetParameter: a parameter given to every node after it, in its scope (`-p name:=value`)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.frontend import expose_action
from launch.utilities import normalize_to_list_of_substitutions

from launch_ros.utilities import evaluate_parameter_dict, normalize_parameter_dict

if TYPE_CHECKING:
    from launch.frontend import Entity, Parser
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType

    from launch_ros.parameters_type import SomeParameterValue


def append_configuration(context: Any, key: str, *items: Any) -> None:
    """Add to a list launch configuration without changing the enclosing scope's list."""
    context.launch_configurations[key] = [*context.launch_configurations.get(key, []), *items]


@expose_action('set_parameter')
class SetParameter(Action):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs['name'] = parser.parse_substitution(entity.get_attr('name'))
        kwargs['value'] = parser.parse_substitution(entity.get_attr('value'))
        return cls, kwargs

    def __init__(self, name: SomeSubstitutionsType, value: SomeParameterValue,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        name = tuple(normalize_to_list_of_substitutions(name))
        self.__param_dict = normalize_parameter_dict({name: value})

    @property
    def name(self) -> Any:
        return next(iter(self.__param_dict))

    @property
    def value(self) -> Any:
        return next(iter(self.__param_dict.values()))

    def execute(self, context: LaunchContext) -> None:
        evaluated = evaluate_parameter_dict(context, self.__param_dict)
        append_configuration(context, 'global_params', *evaluated.items())
