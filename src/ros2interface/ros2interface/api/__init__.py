"""What the verbs of `ros2 interface` share."""

from __future__ import annotations

from ros2cli.verb_context import CliError

KINDS = ('msg', 'srv', 'action')


def interface_packages() -> dict[str, str]:
    from ament_index_python import get_resources
    return get_resources('rosidl_interfaces')


def interfaces_of(package: str) -> list[str]:
    """'kind/Name' of every interface of a package, in the index's order, without duplicates."""
    from ament_index_python import get_resource, has_resource
    if not has_resource('packages', package):
        raise CliError(f"Unknown package '{package}'")
    try:
        content, _ = get_resource('rosidl_interfaces', package)
    except LookupError:
        return []
    names: list[str] = []
    for line in content.splitlines():
        stem = line.rsplit('.', 1)[0]
        kind = stem.split('/', 1)[0]
        if kind in KINDS and '_' not in stem.split('/', 1)[-1] and stem not in names:
            names.append(stem)
    return names
