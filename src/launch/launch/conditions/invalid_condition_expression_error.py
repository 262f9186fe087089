"""InvalidConditionExpressionError: a condition's text is none of true/false/1/0."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from launch.substitution import Substitution


class InvalidConditionExpressionError(ValueError):
    def __init__(self, expression: str, unexpanded_expression: list[Substitution],
                 valid_expressions: list[str]) -> None:
        source = ' + '.join(str(sub) for sub in unexpanded_expression)
        super().__init__(f"invalid condition expression, expected one of "
                         f"[{', '.join(valid_expressions)}] but got '{expression}', expanded "
                         f"from '{source}'")
