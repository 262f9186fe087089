"""Which packages declare which interfaces, from the ament index's `rosidl_interfaces`
resources (one line per file, e.g. 'msg/String.idl', 'msg/String.msg')."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable

from ament_index_python import get_resource, get_resources, has_resource

RESOURCE = 'rosidl_interfaces'


def get_interface_packages() -> dict[str, str]:
    """Package name -> install prefix, for every package that generates interfaces."""
    return get_resources(RESOURCE)


def _listed(package_names: Iterable[str]) -> dict[str, list[str]]:
    names = list(package_names) or list(get_resources(RESOURCE))
    listed = {}
    for package in names:
        if not has_resource('packages', package):
            raise LookupError(f"Unknown package '{package}'")
        try:
            content, _ = get_resource(RESOURCE, package)
        except LookupError:
            continue  # a package without interfaces
        listed[package] = content.splitlines()
    return listed


def _select(package_names: Iterable[str], keep: Callable[[str], str | None]) -> dict:
    """Per package, the distinct names `keep` gives for its files (None drops a file).

    Names with '_' are generated helpers (e.g. 'action/Fibonacci_Goal'), never listed.
    """
    selected = {}
    for package, files in _listed(package_names).items():
        names = {keep(file) for file in files if '_' not in file} - {None}
        if names:
            selected[package] = list(names)
    return selected


def get_interfaces(package_names: Iterable[str] = ()) -> dict[str, list[str]]:
    """Package -> interface names ('msg/String', 'srv/Empty', ...); all packages when none
    are named. LookupError for an unknown package."""
    return _select(package_names, lambda file: file.rsplit('.', 1)[0])


def _of_kind(kind: str) -> Callable[[str], str | None]:
    suffixes = ('.idl', f'.{kind}')

    def keep(file: str) -> str | None:
        stem, dot, suffix = file.rpartition('.')
        if file.startswith(f'{kind}/') and dot and f'.{suffix}' in suffixes:
            return stem
        return None
    return keep


def get_message_interfaces(package_names: Iterable[str] = ()) -> dict[str, list[str]]:
    return _select(package_names, _of_kind('msg'))


def get_service_interfaces(package_names: Iterable[str] = ()) -> dict[str, list[str]]:
    return _select(package_names, _of_kind('srv'))


def get_action_interfaces(package_names: Iterable[str] = ()) -> dict[str, list[str]]:
    return _select(package_names, _of_kind('action'))


def get_interface_path(interface_name: str) -> str:
    """The definition file of 'pkg/msg/Name' or 'pkg/msg/Name.msg'.

    Without a suffix, the file named after its folder ('.msg', '.srv', '.action') if it is
    there, else the '.idl'. ValueError for a malformed name, LookupError if none exists.
    """
    parts = interface_name.split('/')
    if len(parts) < 2:
        raise ValueError(f"Invalid name '{interface_name}'. Expected at least two parts "
                         "separated by '/'")
    if not all(parts):
        raise ValueError(f"Invalid name '{interface_name}'. Must not contain empty parts")
    if '..' in parts:
        raise ValueError(f"Invalid name '{interface_name}'. Must not contain '..'")
    prefix = has_resource('packages', parts[0])
    if not prefix:
        raise LookupError(f"Unknown package '{parts[0]}'")
    path = os.path.join(prefix, 'share', interface_name)
    if '.' not in parts[-1]:
        with_kind = f'{path}.{parts[-2]}'
        if os.path.exists(with_kind):
            return with_kind
        path += '.idl'
    if not os.path.exists(path):
        raise LookupError(f"Could not find the interface '{path}'")
    return path
