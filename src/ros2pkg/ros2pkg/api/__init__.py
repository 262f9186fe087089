"""ros2pkg.api: the package queries behind `ros2 pkg`, under upstream's module name.

Tools written against ros2cli import these (`get_package_names`, `get_prefix_path`,
`get_executable_paths`); `ros2 pkg list/prefix/executables` and `ros2 run` use them
too (`executables`).
"""

from __future__ import annotations

from collections.abc import KeysView

PACKAGE_NOT_FOUND = 'Package not found'


class PackageNotFound(Exception):
    """No package of that name in the ament index."""

    def __init__(self, package_name: str) -> None:
        super().__init__(package_name)
        self.package_name = package_name


def get_package_names() -> KeysView[str]:
    """The names of every package in the ament index (AMENT_PREFIX_PATH)."""
    from ament_index_python.packages import get_packages_with_prefixes
    return get_packages_with_prefixes().keys()


def get_prefix_path(package_name: str) -> str | None:
    """The install prefix of a package; None for an unknown or malformed name."""
    from ament_index_python.packages import PackageNotFoundError, get_package_prefix
    try:
        return get_package_prefix(package_name)
    except (PackageNotFoundError, ValueError):
        return None


def get_executable_paths(*, package_name: str) -> list[str]:
    """Every executable file under <prefix>/lib/<package>/ (as `ros2 run` finds them);
    PackageNotFound for an unknown package."""
    from ros2cli.verb_context import CliError
    try:
        return executables(package_name)[1]
    except CliError:
        raise PackageNotFound(package_name) from None


def executables(package: str) -> tuple[str, list[str]]:
    """(lib dir, every executable file under lib/<package>/, recursively)."""
    import os

    from ament_index_python.packages import PackageNotFoundError, get_package_prefix
    from ros2cli.verb_context import CliError
    try:
        prefix = get_package_prefix(package)
    except (PackageNotFoundError, ValueError):
        raise CliError(f"Package '{package}' not found") from None
    lib = os.path.join(prefix, 'lib', package)
    found = []
    for directory, _, files in os.walk(lib, followlinks=True):
        for name in files:
            path = os.path.join(directory, name)
            if os.path.isfile(path) and os.access(path, os.X_OK):
                found.append(path)
    return lib, sorted(found)


def share_directory(name: str) -> str:
    from ament_index_python.packages import PackageNotFoundError, get_package_share_directory
    try:
        return get_package_share_directory(name)
    except (PackageNotFoundError, ValueError):
        from ros2cli.verb_context import CliError
        raise CliError(PACKAGE_NOT_FOUND) from None


def package_name_completer(**kwargs: object) -> KeysView[str]:
    """argcomplete's completer of package names."""
    return get_package_names()
