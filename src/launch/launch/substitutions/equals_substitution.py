"""EqualsSubstitution: `$(equals a b)`, 'true' when the two values are equal.

Booleans compare as booleans ('1' equals 'true'), numbers as numbers (1.0 equals 1),
anything else as text; None is the empty text.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.substitution import Substitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions
from launch.utilities.type_utils import is_substitution

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext

_BOOLEANS = ('true', 'false', '1', '0')


def _normalized(value: Any) -> list[Substitution]:
    if not is_substitution(value):
        if value is None:
            value = ''
        elif isinstance(value, bool):
            value = str(value).lower()
        else:
            value = str(value)
    return normalize_to_list_of_substitutions(value)


def _is_float(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def values_equal(left: str, right: str) -> bool:
    if left.lower() in _BOOLEANS and right.lower() in _BOOLEANS:
        return (left.lower() in ('true', '1')) == (right.lower() in ('true', '1'))
    if _is_float(left) and _is_float(right):
        return math.isclose(float(left), float(right))
    return left == right


@expose_substitution('equals')
class EqualsSubstitution(Substitution):
    def __init__(self, left: Any, right: Any) -> None:
        self.__left = _normalized(left)
        self.__right = _normalized(right)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if len(data) != 2:
            raise TypeError(f'{cls.__name__} expects 2 arguments')
        return cls, {'left': data[0], 'right': data[1]}

    @property
    def left(self) -> list[Substitution]:
        return self.__left

    @property
    def right(self) -> list[Substitution]:
        return self.__right

    def describe(self) -> str:
        return f'{type(self).__name__}({self.left} {self.right})'

    def perform(self, context: LaunchContext) -> str:
        equal = values_equal(perform_substitutions(context, self.left),
                             perform_substitutions(context, self.right))
        return str(equal).lower()
