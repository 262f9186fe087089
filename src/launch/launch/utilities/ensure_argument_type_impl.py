"""ensure_argument_type(): one TypeError naming the argument, the caller and what is allowed."""

from __future__ import annotations

import collections.abc
import inspect
from collections.abc import Iterable
from typing import Any

_MESSAGE = "{}xpected '{}' to be one of [{}], but got '{}' of type '{}'"


def ensure_argument_type(argument: Any, types: type | Iterable[type], argument_name: str,
                         caller: str | None = None) -> None:
    own = "'ensure_argument_type()' e"
    if not isinstance(types, (type, collections.abc.Iterable)):
        raise TypeError(_MESSAGE.format(own, 'types', 'type, collections.abc.Iterable of type',
                                        types, type(types)))
    if not isinstance(argument_name, str):
        raise TypeError(_MESSAGE.format(own, 'argument_name', 'str', argument_name,
                                        type(argument_name)))
    if caller is not None and not isinstance(caller, str):
        raise TypeError(_MESSAGE.format(own, 'caller', 'str, None', caller, type(caller)))
    candidates = list(types) if isinstance(types, collections.abc.Iterable) else [types]

    def matches(candidate: Any) -> bool:
        if isinstance(argument, candidate):
            return True
        return inspect.isclass(candidate) and issubclass(type(argument), candidate)

    if not any(matches(candidate) for candidate in candidates):
        who = 'E' if caller is None else f"'{caller}' e"
        raise TypeError(_MESSAGE.format(who, argument_name,
                                        ', '.join(str(c) for c in candidates), argument,
                                        type(argument)))
