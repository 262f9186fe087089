"""evaluate_condition_expression(): 'true'/'1' or 'false'/'0' (any case) as a bool."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.conditions.invalid_condition_expression_error import (
    InvalidConditionExpressionError,
)
from launch.utilities import perform_substitutions

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.substitution import Substitution

VALID_TRUE_EXPRESSIONS = ['true', '1']
VALID_FALSE_EXPRESSIONS = ['false', '0']


def evaluate_condition_expression(context: LaunchContext, expression: list[Substitution]
                                  ) -> bool:
    text = perform_substitutions(context, expression).strip().lower()
    if text in VALID_TRUE_EXPRESSIONS:
        return True
    if text in VALID_FALSE_EXPRESSIONS:
        return False
    raise InvalidConditionExpressionError(text, expression,
                                          VALID_TRUE_EXPRESSIONS + VALID_FALSE_EXPRESSIONS)
