"""LocalSubstitution: a value from the context's locals (`event.returncode`, ...)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.substitution import Substitution
from launch.utilities import ensure_argument_type

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class LocalSubstitution(Substitution):
    def __init__(self, expression: str, description: str | None = None) -> None:
        ensure_argument_type(expression, str, 'expression', 'LocalSubstitution')
        self.__expression = expression
        self.__description = description

    @property
    def expression(self) -> str:
        return self.__expression

    @property
    def description(self) -> str | None:
        return self.__description

    def describe(self) -> str:
        return f"LocalVar('{self.description or self.expression}')"

    def perform(self, context: LaunchContext) -> str:
        # The expression is an attribute path into the locals, e.g. 'event.returncode'.
        return eval('locals_.' + self.expression, {}, {'locals_': context.locals})
