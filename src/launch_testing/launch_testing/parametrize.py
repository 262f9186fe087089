"""parametrize: one launch (and one run of every test) per set of arguments, like pytest's."""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterable, Iterator
from typing import Any


def parametrize(argnames: str, argvalues: Iterable[Any]
                ) -> Callable[[Callable[..., Any]], Callable[[], Iterator[Any]]]:
    names = [name.strip() for name in argnames.split(',') if name.strip()]
    values = [value if isinstance(value, tuple) else (value,) for value in argvalues]
    for value in values:
        if len(value) != len(names):
            raise ValueError(f'parametrize: {value!r} does not give one value for each of '
                             f'{names}')

    def decorator(function: Callable[..., Any]) -> Callable[[], Iterator[Any]]:
        @functools.wraps(function)
        def runs() -> Iterator[tuple[Callable[..., Any], dict[str, Any]]]:
            for value in values:
                arguments = dict(zip(names, value, strict=True))
                bound = functools.partial(function, **arguments)
                functools.update_wrapper(bound, function)
                yield bound, arguments

        runs.__parametrized__ = True  # type: ignore[attr-defined]
        timeout = getattr(function, '__ready_to_test_action_timeout__', None)
        if timeout is not None:
            runs.__ready_to_test_action_timeout__ = timeout  # type: ignore[attr-defined]
        return runs
    return decorator
