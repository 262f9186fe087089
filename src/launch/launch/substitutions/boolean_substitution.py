"""NotSubstitution, AndSubstitution, OrSubstitution, AnySubstitution, AllSubstitution.

Each reads its operands as booleans (true/false/1/0 and YAML's spellings) and gives
'true' or 'false'.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.substitution import Substitution
from launch.substitutions._operand_pair import OperandPairSubstitution
from launch.substitutions.substitution_failure import SubstitutionFailure
from launch.utilities import normalize_to_list_of_substitutions
from launch.utilities.type_utils import perform_typed_substitution

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


def _as_bool(context: LaunchContext, value: list[Substitution]) -> bool:
    try:
        return perform_typed_substitution(context, value, bool)
    except (TypeError, ValueError) as error:
        raise SubstitutionFailure(error) from None


def _text(result: bool) -> str:
    return str(result).lower()


@expose_substitution('not')
class NotSubstitution(Substitution):
    def __init__(self, value: SomeSubstitutionsType) -> None:
        self.__value = normalize_to_list_of_substitutions(value)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if len(data) != 1:
            raise TypeError('not substitution expects 1 argument')
        return cls, {'value': data[0]}

    @property
    def value(self) -> list[Substitution]:
        return self.__value

    def describe(self) -> str:
        return f'NotSubstitution({self.value})'

    def perform(self, context: LaunchContext) -> str:
        return _text(not _as_bool(context, self.value))


class _BinarySubstitution(OperandPairSubstitution):
    _tag = ''
    _combine: Callable[[bool, bool], bool]

    @classmethod
    def _arity_error(cls) -> str:
        return f'{cls._tag} substitution expects 2 arguments'

    def perform(self, context: LaunchContext) -> str:
        left = _as_bool(context, self.left)
        right = _as_bool(context, self.right)
        return _text(type(self)._combine(left, right))


@expose_substitution('and')
class AndSubstitution(_BinarySubstitution):
    _tag = 'and'

    @staticmethod
    def _combine(left: bool, right: bool) -> bool:
        return left and right


@expose_substitution('or')
class OrSubstitution(_BinarySubstitution):
    _tag = 'or'

    @staticmethod
    def _combine(left: bool, right: bool) -> bool:
        return left or right

    def describe(self) -> str:
        # Upstream Jazzy's OrSubstitution describes itself as AndSubstitution (a slip there);
        # `ros2 launch --print` shows that text, so this one does too.
        return f'AndSubstitution({self.left} {self.right})'


class _ManySubstitution(Substitution):
    _reduce: Callable[[Iterable[bool]], bool]

    def __init__(self, *args: SomeSubstitutionsType) -> None:
        self.__args = [normalize_to_list_of_substitutions(arg) for arg in args]

    @classmethod
    def parse(cls, data: Iterable[Any]) -> tuple[type, dict[str, Any]]:
        return cls, {'args': data}

    @property
    def args(self) -> list[list[Substitution]]:
        return self.__args

    def describe(self) -> str:
        return f'{type(self).__name__}({" ".join(str(arg) for arg in self.args)})'

    def perform(self, context: LaunchContext) -> str:
        values = [_as_bool(context, arg) for arg in self.args]
        return _text(type(self)._reduce(values))


@expose_substitution('any')
class AnySubstitution(_ManySubstitution):
    _reduce = any

    def __init__(self, *args: SomeSubstitutionsType, **kwargs: Any) -> None:
        # The front end hands the operands over as `args=[...]`.
        super().__init__(*args, *kwargs.pop('args', ()))


@expose_substitution('all')
class AllSubstitution(_ManySubstitution):
    _reduce = all

    def __init__(self, *args: SomeSubstitutionsType, **kwargs: Any) -> None:
        super().__init__(*args, *kwargs.pop('args', ()))
