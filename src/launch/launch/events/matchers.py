"""matches_action(): an event matcher for events about one given action."""

from collections.abc import Callable
from typing import Any


def matches_action(target_action: Any) -> Callable[[Any], bool]:
    return lambda action: action is target_action
