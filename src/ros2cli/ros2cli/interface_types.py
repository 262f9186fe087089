"""Interface types by name: the generated class of 'pkg/msg/Name' and back.

rosidl_runtime_py is imported inside the functions, so a verb that names no type never loads
it.
"""

from __future__ import annotations

from typing import Any


def import_type(name: str, kind: str) -> Any:
    """The generated class 'pkg/kind/Name' or 'pkg/Name' names (kind = msg, srv or action;
    also a service's parts, e.g. 'pkg/srv/Name_Event'); ValueError(name) for anything else."""
    from rosidl_runtime_py.utilities import get_interface

    parts = name.split('/')
    if len(parts) == 2:
        parts = [parts[0], kind, parts[1]]
    if len(parts) != 3 or not all(parts) or parts[1] != kind:
        raise ValueError(name)
    try:
        return get_interface('/'.join(parts))
    except (ImportError, AttributeError, ValueError):
        raise ValueError(name) from None


def type_name(msg_class: Any) -> str:
    """'pkg/msg/Name' of a generated class (services: 'pkg/srv/Name_Request')."""
    module = msg_class.__module__.split('.')
    return f'{module[0]}/{module[1]}/{msg_class.__name__}'
