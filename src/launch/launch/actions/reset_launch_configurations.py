"""ResetLaunchConfigurations: `<reset>`, forgets every launch configuration but those given."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.frontend.expose import expose_action
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_action('reset')
class ResetLaunchConfigurations(Action):
    def __init__(self, launch_configurations: dict[SomeSubstitutionsType, SomeSubstitutionsType]
                 | None = None, **kwargs: Any
                 ) -> None:
        super().__init__(**kwargs)
        self.__launch_configurations = launch_configurations

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        keeps = parse_keeps(entity, parser)
        if keeps is not None:
            kwargs['launch_configurations'] = keeps
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        kept = {}
        for key, value in (self.__launch_configurations or {}).items():
            kept[perform_substitutions(context, normalize_to_list_of_substitutions(key))] = \
                perform_substitutions(context, normalize_to_list_of_substitutions(value))
        context.launch_configurations.clear()
        context.launch_configurations.update(kept)


def parse_keeps(entity: Entity, parser: Parser) -> dict[Any, Any] | None:
    """The `<keep name= value=/>` children of a tag, as {name: value}, None when none."""

    from launch.frontend.entity import Entity as EntityType
    keeps = entity.get_attr('keep', data_type=list[EntityType], optional=True)
    if keeps is None:
        return None
    result = {tuple(parser.parse_substitution(keep.get_attr('name'))):
              parser.parse_substitution(keep.get_attr('value')) for keep in keeps}
    for keep in keeps:
        keep.assert_entity_completely_parsed()
    return result
