"""Message definitions for MCAP schemas, gathered as rosbag2's LocalMessageDefinitionSource does.

A `ros2msg` schema holds the type's own `.msg` file text followed by every type it depends
on, each after a line of 80 `=` and a `MSG: pkg/Name` line. When a type or one of its
dependencies has no `.msg` file (an interface written in IDL), the whole schema is built from
`.idl` files instead (`ros2idl`: `IDL: pkg/msg/Name` sections, dependencies from `#include`
lines). Service types (and service event topics) get the service's `.srv` text after
`SRV: pkg/srv/Name`, each dependency as `.msg` if it has one, else as `.idl`. A type whose
files cannot be found gets an empty definition (encoding ''), as in Jazzy.
"""

from __future__ import annotations

import os
import re

DELIMITER = '=' * 80 + '\n'
_TYPE_NAME = re.compile(r'^([a-zA-Z0-9_]+)/(?:msg/|srv/)?([a-zA-Z0-9_]+)$')
_FIELD_TYPE = re.compile(r'(?:^|\n)\s*([a-zA-Z0-9_/]+)(?:\[[^\]]*\])?\s+')
_IDL_INCLUDE = re.compile(r'(?:^|\n)#include\s+(?:"|<)([a-zA-Z0-9_/]+)\.idl(?:"|>)')
_PRIMITIVES = {'bool', 'byte', 'char', 'float32', 'float64', 'int8', 'uint8', 'int16',
               'uint16', 'int32', 'uint32', 'int64', 'uint64', 'string', 'wstring'}
_HEADINGS = {'msg': 'MSG', 'idl': 'IDL', 'srv': 'SRV'}
MAX_DEPTH = 50


class _NotFound(Exception):
    pass


def _msg_dependencies(text: str, package: str) -> list[str]:
    found = {name if '/' in name else f'{package}/{name}'
             for name in _FIELD_TYPE.findall(text) if name not in _PRIMITIVES}
    return sorted(found)


def _load(type_name: str, kind: str) -> tuple[str, list[str]]:
    """(file text, sorted dependencies) of `type_name` as a 'msg', 'idl' or 'srv' file."""
    from ament_index_python.packages import PackageNotFoundError, get_package_share_directory

    match = _TYPE_NAME.match(type_name)
    if not match:
        raise _NotFound(type_name)
    package, name = match.groups()
    try:
        share = get_package_share_directory(package)
    except (PackageNotFoundError, ValueError, OSError):
        raise _NotFound(type_name) from None
    folder = 'srv' if kind == 'srv' else 'msg'
    try:
        with open(os.path.join(share, folder, f'{name}.{kind}'), encoding='utf-8') as stream:
            text = stream.read()
    except OSError:
        raise _NotFound(type_name) from None
    if kind == 'idl':
        return text, sorted(set(_IDL_INCLUDE.findall(text)))
    dependencies = _msg_dependencies(text, package)
    if kind == 'srv' and not dependencies:
        dependencies = sorted(set(_IDL_INCLUDE.findall(text)))
    return text, dependencies


def _section(type_name: str, kind: str) -> str:
    return DELIMITER + f'{_HEADINGS[kind]}: {type_name}\n'


def _recursive(type_name: str, kind: str, seen: set[tuple[str, str]], depth: int) -> str:
    """The text of `type_name` followed by each dependency not yet in `seen`."""
    if depth <= 0:
        raise _NotFound(type_name)
    text, dependencies = _load(type_name, kind)
    for dependency in dependencies:
        if (dependency, kind) in seen:
            continue
        seen.add((dependency, kind))
        text += '\n' + _section(dependency, kind) + _recursive(dependency, kind, seen,
                                                               depth - 1)
    return text


def _service(service: str) -> tuple[str, str]:
    text, dependencies = _load(service, 'srv')
    seen = {(service, 'srv')}
    result = _section(service, 'srv') + text
    encoding = 'ros2msg'  # Jazzy says 'unknown' for a service of primitives only: ros2msg
    for dependency in dependencies:
        if (dependency, 'msg') in seen:
            continue
        seen.add((dependency, 'msg'))
        # Jazzy's heading stays when the .msg is missing, an empty MSG section before the IDL.
        result += '\n' + _section(dependency, 'msg')
        try:
            result += _recursive(dependency, 'msg', seen, MAX_DEPTH)
            encoding = 'ros2msg'
            continue
        except _NotFound:
            pass
        if (dependency, 'idl') not in seen:
            seen.add((dependency, 'idl'))
            result += '\n' + _section(dependency, 'idl') + _recursive(dependency, 'idl', seen,
                                                                      MAX_DEPTH)
            encoding = 'ros2idl'
    return encoding, result


def full_text(type_name: str) -> tuple[str, str]:
    """(encoding, definition) for a topic type; service event types use their service."""
    try:
        if '/srv/' in type_name:
            return _service(type_name.removesuffix('_Event'))
        try:
            return 'ros2msg', _recursive(type_name, 'msg', set(), MAX_DEPTH)
        except _NotFound:
            return 'ros2idl', _section(type_name, 'idl') + _recursive(type_name, 'idl', set(),
                                                                      MAX_DEPTH)
    except _NotFound:
        return '', ''
