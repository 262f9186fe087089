"""is_a / is_a_subclass: isinstance checks that also accept a class for the object."""

from __future__ import annotations

import inspect
from typing import Any


def isclassinstance(obj: Any) -> bool:
    return hasattr(obj, '__class__')


def is_a(obj: Any, entity_type: type) -> bool:
    """True when obj is an instance of entity_type."""
    if not isclassinstance(obj):
        raise RuntimeError(f"obj '{obj}' is not a class instance")
    if not inspect.isclass(entity_type):
        raise RuntimeError(f"entity_type '{entity_type}' is not a class")
    return isinstance(obj, entity_type)


def is_a_subclass(obj: Any, entity_type: type) -> bool:
    """True when obj is an instance of entity_type, or a class derived from it."""
    if is_a(obj, entity_type):
        return True
    return inspect.isclass(obj) and issubclass(obj, entity_type)
