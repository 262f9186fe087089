"""EnvironmentVariable: `$(env NAME [default])`."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.substitution import Substitution
from launch.substitutions.substitution_failure import SubstitutionFailure
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_substitution('env')
class EnvironmentVariable(Substitution):
    def __init__(self, name: SomeSubstitutionsType, *,
                 default_value: SomeSubstitutionsType | None = None) -> None:
        self.__name = normalize_to_list_of_substitutions(name)
        self.__default_value = (None if default_value is None
                                else normalize_to_list_of_substitutions(default_value))

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if not 1 <= len(data) <= 2:
            raise TypeError('env substitution expects 1 or 2 arguments')
        kwargs = {'name': data[0]}
        if len(data) == 2:
            kwargs['default_value'] = data[1]
        return cls, kwargs

    @property
    def name(self) -> list[Substitution]:
        return self.__name

    @property
    def default_value(self) -> list[Substitution] | None:
        return self.__default_value

    def describe(self) -> str:
        return 'EnvVar({})'.format(' + '.join(sub.describe() for sub in self.name))

    def perform(self, context: LaunchContext) -> str:
        default = (None if self.default_value is None
                   else perform_substitutions(context, self.default_value))
        name = perform_substitutions(context, self.name)
        value = context.environment.get(name, default)
        if value is None:
            raise SubstitutionFailure(f"environment variable '{name}' does not exist")
        return value
