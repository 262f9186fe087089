"""Message definitions for MCAP schemas, gathered as rosbag2's LocalMessageDefinitionSource does.

A schema holds the type's own `.msg` file text followed by every type it depends on, each
after a line of 80 `=` and a `MSG: pkg/Name` line. Service event topics get the service's
`.srv` text after `SRV: pkg/srv/Name`. A type whose files cannot be found gets an empty
definition (encoding ''), as in Jazzy.
"""

from __future__ import annotations

import os
import re

DELIMITER = '=' * 80 + '\n'
_TYPE_NAME = re.compile(r'^([a-zA-Z0-9_]+)/(?:msg/|srv/)?([a-zA-Z0-9_]+)$')
_FIELD_TYPE = re.compile(r'(?:^|\n)\s*([a-zA-Z0-9_/]+)(?:\[[^\]]*\])?\s+')
_PRIMITIVES = {'bool', 'byte', 'char', 'float32', 'float64', 'int8', 'uint8', 'int16',
               'uint16', 'int32', 'uint32', 'int64', 'uint64', 'string', 'wstring'}


class _NotFound(Exception):
    pass


def _load(type_name: str, kind: str) -> tuple[str, list[str]]:
    """(file text, sorted dependencies) of `type_name` ('msg' or 'srv')."""
    from ament_index_python.packages import PackageNotFoundError, get_package_share_directory

    match = _TYPE_NAME.match(type_name)
    if not match:
        raise _NotFound(type_name)
    package, name = match.groups()
    try:
        share = get_package_share_directory(package)
    except (PackageNotFoundError, ValueError, OSError):
        raise _NotFound(type_name) from None
    path = os.path.join(share, kind, f'{name}.{kind}')
    try:
        with open(path, encoding='utf-8') as stream:
            text = stream.read()
    except OSError:
        raise _NotFound(type_name) from None
    dependencies = set()
    for found in _FIELD_TYPE.findall(text):
        if found in _PRIMITIVES or found == '---':
            continue
        dependencies.add(found if '/' in found else f'{package}/{found}')
    return text, sorted(dependencies)


def _with_dependencies(text: str, dependencies: list[str], seen: set[str], depth: int = 50
                       ) -> str:
    result = text
    for dependency in dependencies:
        if dependency in seen:
            continue
        seen.add(dependency)
        dep_text, dep_deps = _load(dependency, 'msg')
        result += '\n' + DELIMITER + f'MSG: {dependency}\n'
        result += _with_dependencies(dep_text, dep_deps, seen, depth - 1) if depth else dep_text
    return result


def full_text(type_name: str) -> tuple[str, str]:
    """(encoding, definition) for a topic type; service event types use their service."""
    try:
        if '/srv/' in type_name and type_name.endswith('_Event'):
            service = type_name[:-len('_Event')]
            text, dependencies = _load(service, 'srv')
            seen = {service}
            header = DELIMITER + f'SRV: {service}\n'
            return 'ros2msg', header + _with_dependencies(text, dependencies, seen)
        text, dependencies = _load(type_name, 'msg')
        return 'ros2msg', _with_dependencies(text, dependencies, set())
    except _NotFound:
        return '', ''
