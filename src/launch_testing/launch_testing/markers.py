"""Markers for generate_test_description and test methods (upstream's names)."""

from __future__ import annotations

import functools
import time
from collections.abc import Callable
from typing import Any


def keep_alive(test_description: Callable[..., Any]) -> Callable[..., Any]:
    """Keep the launch running after its processes exit, until the active tests are done.

    Without it the launch stops when nothing is left running, and active tests that had not
    finished then fail with 'Launch stopped before the active tests finished.'
    """
    markers = getattr(test_description, '__markers__', None)
    if markers is None:
        markers = test_description.__markers__ = {}
    markers['keep_alive'] = True
    return test_description


def retry_on_failure(*, times: int, delay: float | None = None
                     ) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Run a test method up to `times` times while it fails an assertion."""
    if times < 1:
        raise ValueError(f'retry_on_failure: times must be at least 1, got {times}')

    def decorator(function: Callable[..., Any]) -> Callable[..., Any]:
        @functools.wraps(function)
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            for _ in range(times - 1):
                try:
                    return function(*args, **kwargs)
                except AssertionError:
                    if delay:
                        time.sleep(delay)
            return function(*args, **kwargs)
        return wrapper
    return decorator
