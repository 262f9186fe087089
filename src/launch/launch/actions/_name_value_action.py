"""The shape shared by `<set_env>` and `<let>`: a name and a value, set into a mapping."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from collections.abc import MutableMapping

    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType
    from launch.substitution import Substitution


class NameValueAction(Action):
    """Sets `name` to `value` in the mapping of the context that `_mapping` names."""

    def __init__(self, name: SomeSubstitutionsType, value: SomeSubstitutionsType,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__name = normalize_to_list_of_substitutions(name)
        self.__value = normalize_to_list_of_substitutions(value)

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs['name'] = parser.parse_substitution(entity.get_attr('name'))
        kwargs['value'] = parser.parse_substitution(entity.get_attr('value'))
        return cls, kwargs

    @property
    def name(self) -> list[Substitution]:
        return self.__name

    @property
    def value(self) -> list[Substitution]:
        return self.__value

    @staticmethod
    def _mapping(context: LaunchContext) -> MutableMapping[str, str]:
        raise NotImplementedError

    def execute(self, context: LaunchContext) -> None:
        self._mapping(context)[perform_substitutions(context, self.name)] = \
            perform_substitutions(context, self.value)
