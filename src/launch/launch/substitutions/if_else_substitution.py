"""IfElseSubstitution: `$(if cond a [b])`, one of two values chosen by a boolean."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.substitution import Substitution
from launch.substitutions.boolean_substitution import _as_bool
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_substitution('if')
class IfElseSubstitution(Substitution):
    def __init__(self, condition: SomeSubstitutionsType,
                 if_value: SomeSubstitutionsType = '',
                 else_value: SomeSubstitutionsType = '') -> None:
        if if_value == else_value == '':
            raise RuntimeError('One of if_value and else_value must be specified')
        self._condition = normalize_to_list_of_substitutions(condition)
        self._if_value = normalize_to_list_of_substitutions(if_value)
        self._else_value = normalize_to_list_of_substitutions(else_value)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if not 2 <= len(data) <= 3:
            raise TypeError('if substitution expects from 2 or 3 arguments')
        kwargs = {'condition': data[0], 'if_value': data[1]}
        if len(data) == 3:
            kwargs['else_value'] = data[2]
        return cls, kwargs

    @property
    def condition(self) -> list[Substitution]:
        return self._condition

    @property
    def if_value(self) -> list[Substitution]:
        return self._if_value

    @property
    def else_value(self) -> list[Substitution]:
        return self._else_value

    def describe(self) -> str:
        return f'IfElseSubstitution({self.condition}, {self.if_value}, {self.else_value})'

    def perform(self, context: LaunchContext) -> str:
        chosen = self.if_value if _as_bool(context, self.condition) else self.else_value
        return perform_substitutions(context, chosen)
