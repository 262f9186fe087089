"""event_named(): an event matcher by event name."""

from collections.abc import Callable
from typing import Any


def event_named(name: str) -> Callable[[Any], bool]:
    return lambda event: event.name == name
