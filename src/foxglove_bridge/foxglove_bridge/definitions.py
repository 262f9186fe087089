"""Full `ros2msg` schema texts, built the way upstream's foxglove_bridge builds them.

A channel's schema is the type's own .msg text followed, for every message type it uses
(depth first, each once, in sorted order per level), by a line of 80 '=' characters, a
`MSG: pkg/Type` line and that type's text. Clients (Foxglove, Lichtblick, @foxglove/rosmsg)
parse exactly this concatenation. Services give one schema per request and response half.
"""

from __future__ import annotations

import re
from functools import cache, lru_cache
from pathlib import Path
from typing import Any

from ament_index_python import get_package_share_directory, get_resource
from rosidl_runtime_py.utilities import get_interface

TYPE_NAME = re.compile(r'^([a-zA-Z0-9_]+)/(?:(msg|srv|action)/)?([a-zA-Z0-9_]+)$')
# The type of a field in a .msg text ("geometry_msgs/Vector3" in "geometry_msgs/Vector3[] v").
FIELD_TYPE = re.compile(r'(?:^|\n)\s*([a-zA-Z0-9_/]+)(?:\[[^\]]*\])?\s+')
PRIMITIVES = frozenset({'bool', 'byte', 'char', 'float32', 'float64', 'int8', 'uint8', 'int16',
                        'uint16', 'int32', 'uint32', 'int64', 'uint64', 'string', 'wstring'})
SEPARATOR = '=' * 80 + '\n'
SRV_SPLIT = re.compile(r'^---\s*$', re.MULTILINE)


class DefinitionNotFound(LookupError):
    pass


def _interface_file(package: str, filename: str) -> Path:
    index, _ = get_resource('rosidl_interfaces', package)
    for line in index.splitlines():
        if Path(line).name == filename:
            return Path(get_package_share_directory(package)) / line
    raise DefinitionNotFound(f'{package}/{filename}')


@cache
def _own_text(type_name: str) -> tuple[str, str]:
    """(text, package) of one message, or of one half of a service ('pkg/srv/X_Request')."""
    match = TYPE_NAME.match(type_name)
    if not match:
        raise DefinitionNotFound(type_name)
    package, kind, name = match.groups()
    try:
        if kind == 'srv':
            base, _, half = name.rpartition('_')
            if half not in ('Request', 'Response'):
                raise DefinitionNotFound(type_name)
            parts = SRV_SPLIT.split(_interface_file(package, base + '.srv').read_text())
            return parts[0 if half == 'Request' else 1].strip('\n') + '\n', package
        return _interface_file(package, name + '.msg').read_text(), package
    except (OSError, LookupError) as error:
        raise DefinitionNotFound(type_name) from error


def _dependencies(text: str, package: str) -> list[str]:
    found = set()
    for field_type in FIELD_TYPE.findall(text):
        if field_type in PRIMITIVES:
            continue
        found.add(field_type if '/' in field_type else f'{package}/{field_type}')
    return sorted(found)


@lru_cache(maxsize=256)
def full_text(type_name: str) -> str:
    """The concatenated ros2msg schema of 'pkg/msg/Type' or 'pkg/srv/Type_Request'."""
    seen: set[str] = set()

    def append(name: str) -> str:
        text, package = _own_text(name)
        for dependency in _dependencies(text, package):
            if dependency not in seen:
                seen.add(dependency)
                text += '\n' + SEPARATOR + f'MSG: {dependency}\n' + append(dependency)
        return text

    return append(type_name)


def interface_class(type_name: str) -> Any:
    """The generated Python class of 'pkg/msg/Type' or 'pkg/srv/Type'."""
    match = TYPE_NAME.match(type_name)
    if not match or not match.group(2):
        raise DefinitionNotFound(type_name)
    try:
        return get_interface(type_name)
    except (ImportError, AttributeError, ValueError) as error:
        raise DefinitionNotFound(type_name) from error
