"""launch_ros.substitutions: package paths and executables from the ament index."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

from launch._missing import module_getattr
from launch.frontend.expose import expose_substitution, one_argument
from launch.substitution import (
    SomeSubstitutionsType,
    Substitution,
    describe,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from launch.substitutions import SubstitutionFailure

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


@expose_substitution('find-pkg-prefix')
class FindPackagePrefix(Substitution):
    """The install prefix of a package."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {'package': one_argument('find-pkg-prefix', data)}

    def __init__(self, package: SomeSubstitutionsType) -> None:
        self.package = normalize_to_list_of_substitutions(package)

    def find(self, package: str) -> str:
        from ament_index_python.packages import get_package_prefix
        return get_package_prefix(package)

    def perform(self, context: LaunchContext) -> str:
        return self.find(perform_substitutions(context, self.package))

    def describe(self) -> str:
        return f'Pkg(pkg={describe(self.package)})'


@expose_substitution('find-pkg-share')
class FindPackageShare(FindPackagePrefix):
    """The share directory of a package."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {'package': one_argument('find-pkg-share', data)}

    def find(self, package: str) -> str:
        from ament_index_python.packages import get_package_share_directory
        return get_package_share_directory(package)


@expose_substitution('exec-in-pkg')
class ExecutableInPackage(FindPackagePrefix):
    """lib/<package>/<executable>, found as `ros2 run` finds it."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {'executable': data[0], 'package': data[1]}

    def __init__(self, executable: SomeSubstitutionsType, package: SomeSubstitutionsType
                 ) -> None:
        super().__init__(package)
        self.executable = normalize_to_list_of_substitutions(executable)

    def perform(self, context: LaunchContext) -> str:
        package = perform_substitutions(context, self.package)
        executable = perform_substitutions(context, self.executable)
        libexec = os.path.join(super().find(package), 'lib', package)
        path = os.path.join(libexec, executable)
        if not (os.path.isfile(path) and os.access(path, os.X_OK)):
            raise SubstitutionFailure(f"executable '{executable}' not found on the libexec "
                                      f"directory '{libexec}'")
        return path

    def describe(self) -> str:
        return f'ExecInPkg(pkg={describe(self.package)}, exec={describe(self.executable)})'


__all__ = ['ExecutableInPackage', 'FindPackagePrefix', 'FindPackageShare']

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
