"""The shape shared by the substitutions of two operands ($(and a b), $(equals a b), ...)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from launch.substitution import Substitution
from launch.utilities import normalize_to_list_of_substitutions


class OperandPairSubstitution(Substitution):
    """Holds `left` and `right` as lists of substitutions; subclasses say what they give."""

    def __init__(self, left: Any, right: Any) -> None:
        self.__left = self._operand(left)
        self.__right = self._operand(right)

    @staticmethod
    def _operand(value: Any) -> list[Substitution]:
        return normalize_to_list_of_substitutions(value)

    @classmethod
    def _arity_error(cls) -> str:
        return f'{cls.__name__} expects 2 arguments'

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if len(data) != 2:
            raise TypeError(cls._arity_error())
        return cls, {'left': data[0], 'right': data[1]}

    @property
    def left(self) -> list[Substitution]:
        return self.__left

    @property
    def right(self) -> list[Substitution]:
        return self.__right

    def describe(self) -> str:
        return f'{type(self).__name__}({self.left} {self.right})'
