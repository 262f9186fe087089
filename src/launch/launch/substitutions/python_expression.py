"""PythonExpression: `$(eval 'expression' [modules])`, the text of a Python expression.

The expression sees the modules named in `python_modules` (default: math) by name, and, for
upstream compatibility, math's functions and constants without the `math.` prefix.
"""

from __future__ import annotations

import collections.abc
import importlib
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.substitution import Substitution
from launch.utilities import (
    ensure_argument_type,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_substitution('eval')
class PythonExpression(Substitution):
    def __init__(self, expression: SomeSubstitutionsType,
                 python_modules: SomeSubstitutionsType = ('math',)) -> None:
        allowed = (str, Substitution, collections.abc.Iterable)
        ensure_argument_type(expression, allowed, 'expression', 'PythonExpression')
        ensure_argument_type(python_modules, allowed, 'python_modules', 'PythonExpression')
        self.__expression = normalize_to_list_of_substitutions(expression)
        self.__python_modules = normalize_to_list_of_substitutions(python_modules)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if not 1 <= len(data) <= 2:
            raise TypeError('eval substitution expects 1 or 2 arguments')
        kwargs: dict[str, Any] = {'expression': data[0]}
        if len(data) == 2:
            # The second argument is plain text: module names separated by commas.
            text = ''.join(sub.perform(None) for sub in data[1])
            kwargs['python_modules'] = [name.strip() for name in text.split(',') if name.strip()]
        return cls, kwargs

    @property
    def expression(self) -> list[Substitution]:
        return self.__expression

    @property
    def python_modules(self) -> list[Substitution]:
        return self.__python_modules

    def describe(self) -> str:
        return 'PythonExpr({}, [{}])'.format(
            ' + '.join(sub.describe() for sub in self.expression),
            ', '.join(sub.describe() for sub in self.python_modules))

    def perform(self, context: LaunchContext) -> str:
        names: dict[str, Any] = {}
        for sub in self.python_modules:
            module = importlib.import_module(context.perform_substitution(sub))
            if module.__name__ == 'math':
                names.update(vars(module))
            names[module.__name__] = module
        return str(eval(perform_substitutions(context, self.expression), {}, names))
