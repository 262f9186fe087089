"""ready_to_test_action_timeout: how long to wait for ReadyToTest (default 15 s)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def ready_to_test_action_timeout(timeout: float) -> Callable[[Callable[..., Any]], Any]:
    def decorator(function: Callable[..., Any]) -> Callable[..., Any]:
        function.__ready_to_test_action_timeout__ = timeout  # type: ignore[attr-defined]
        return function
    return decorator
