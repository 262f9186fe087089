"""Parameter: the value SetParameter gave a parameter earlier in the launch (`$(param name)`)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.frontend import expose_substitution
from launch.launch_introspector import format_substitutions
from launch.substitutions import SubstitutionFailure
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from launch import Substitution

if TYPE_CHECKING:
    from collections.abc import Iterable

    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_substitution('param')
class Parameter(Substitution):
    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        if not data or len(data) > 2:
            raise TypeError('param substitution expects 1 or 2 arguments')
        kwargs: dict[str, Any] = {'name': data[0]}
        if len(data) == 2:
            kwargs['default'] = data[1]
        return cls, kwargs

    def __init__(self, name: SomeSubstitutionsType,
                 default: Any | Iterable[Any] | None = None) -> None:
        self.__name = normalize_to_list_of_substitutions(name)
        self.__default = None if default is None else normalize_to_list_of_substitutions(
            default)

    @property
    def name(self) -> list[Substitution]:
        return self.__name

    @property
    def default(self) -> list[Substitution] | None:
        return self.__default

    def describe(self) -> str:
        return f'Parameter(name={format_substitutions(self.__name)})'

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.__name)
        for param in reversed(context.launch_configurations.get('global_params') or ()):
            if isinstance(param, tuple) and param[0] == name:
                return str(param[1])
        if self.__default is not None:
            return perform_substitutions(context, self.__default)
        raise SubstitutionFailure(f"parameter '{name}' not found")
