"""LaunchConfiguration: `$(var name [default])`, a launch argument or configuration."""

from __future__ import annotations

import collections.abc
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.substitution import Substitution
from launch.substitutions.substitution_failure import SubstitutionFailure
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from collections.abc import Iterable

    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_substitution('var')
class LaunchConfiguration(Substitution):
    def __init__(self, variable_name: SomeSubstitutionsType, *,
                 default: Any | Iterable[Any] | None = None) -> None:
        self.__variable_name = normalize_to_list_of_substitutions(variable_name)
        self.__default: list[Substitution] | None = None
        if default is not None:
            # Anything that is neither text nor a substitution (a number...) is taken as text.
            items = default if isinstance(default, collections.abc.Iterable) and not isinstance(
                default, str) else [default]
            self.__default = normalize_to_list_of_substitutions(
                [item if isinstance(item, (str, Substitution)) else str(item) for item in items])

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if not 1 <= len(data) <= 2:
            raise TypeError('var substitution expects 1 or 2 arguments')
        kwargs = {'variable_name': data[0]}
        if len(data) == 2:
            kwargs['default'] = data[1]
        return cls, kwargs

    @property
    def variable_name(self) -> list[Substitution]:
        return self.__variable_name

    def describe(self) -> str:
        return 'LaunchConfig({})'.format(' + '.join(s.describe() for s in self.variable_name))

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.__variable_name)
        if name in context.launch_configurations:
            return context.launch_configurations[name]
        if self.__default is None:
            raise SubstitutionFailure(f"launch configuration '{name}' does not exist")
        return perform_substitutions(context, self.__default)
