"""SetRemap: a remapping rule given to every node after it, in its scope."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.frontend import expose_action
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from launch_ros.actions.set_parameter import append_configuration

if TYPE_CHECKING:
    from launch.frontend import Entity, Parser
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_action('set_remap')
class SetRemap(Action):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs['src'] = parser.parse_substitution(entity.get_attr('from'))
        kwargs['dst'] = parser.parse_substitution(entity.get_attr('to'))
        return cls, kwargs

    def __init__(self, src: SomeSubstitutionsType, dst: SomeSubstitutionsType,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__src = normalize_to_list_of_substitutions(src)
        self.__dst = normalize_to_list_of_substitutions(dst)

    @property
    def src(self) -> list[Any]:
        return self.__src

    @property
    def dst(self) -> list[Any]:
        return self.__dst

    def execute(self, context: LaunchContext) -> None:
        rule = (perform_substitutions(context, self.__src),
                perform_substitutions(context, self.__dst))
        append_configuration(context, 'ros_remaps', rule)
