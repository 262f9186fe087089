"""FindPackagePrefix / FindPackageShare: a package's install prefix and share directory."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.frontend import expose_substitution
from launch.launch_introspector import format_substitutions
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from launch import SomeSubstitutionsType, Substitution

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


def _one_argument(name: str, data: list[list[Substitution]]) -> list[Substitution]:
    if len(data) != 1:
        raise TypeError(f'$({name} ...) takes one argument, got {len(data)}')
    return data[0]


class FindPackage(Substitution):
    """Something found for a package (subclasses say what, in find()); upstream's base."""

    _tag = 'find-pkg'

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {'package': _one_argument(cls._tag, data)}

    def __init__(self, package: SomeSubstitutionsType) -> None:
        self.package = normalize_to_list_of_substitutions(package)

    def find(self, package: str) -> str:
        raise NotImplementedError()

    def perform(self, context: LaunchContext) -> str:
        return self.find(perform_substitutions(context, self.package))

    def describe(self) -> str:
        # `ros2 launch --print` shows the class: FindPackageShare(pkg='turtlesim').
        return f'{type(self).__name__}(pkg={format_substitutions(self.package)})'


@expose_substitution('find-pkg-prefix')
class FindPackagePrefix(FindPackage):
    """The install prefix of a package."""

    _tag = 'find-pkg-prefix'

    def find(self, package: str) -> str:
        from ament_index_python.packages import get_package_prefix
        return get_package_prefix(package)


@expose_substitution('find-pkg-share')
class FindPackageShare(FindPackage):
    """The share directory of a package."""

    _tag = 'find-pkg-share'

    def find(self, package: str) -> str:
        from ament_index_python.packages import get_package_share_directory
        return get_package_share_directory(package)
