"""post_shutdown_test: marks a TestCase class to run once the launched processes stopped."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def post_shutdown_test() -> Callable[[type], type]:
    def decorator(test_item: Any) -> type:
        if not isinstance(test_item, type):
            raise TypeError('post_shutdown_test decorates test classes (unittest.TestCase), '
                            f'not {type(test_item).__name__}')
        test_item.__post_shutdown_test__ = True
        return test_item
    return decorator
