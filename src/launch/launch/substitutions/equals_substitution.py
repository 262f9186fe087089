"""EqualsSubstitution: `$(equals a b)`, 'true' when the two values are equal.

Booleans compare as booleans ('1' equals 'true'), numbers as numbers (1.0 equals 1),
anything else as text; None is the empty text.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.substitution import Substitution
from launch.substitutions._operand_pair import OperandPairSubstitution
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
class EqualsSubstitution(OperandPairSubstitution):
    _operand = staticmethod(_normalized)

    def perform(self, context: LaunchContext) -> str:
        equal = values_equal(perform_substitutions(context, self.left),
                             perform_substitutions(context, self.right))
        return str(equal).lower()
