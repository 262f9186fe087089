"""ExecutableInPackage: lib/<package>/<executable>, found as `ros2 run` finds it."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

from launch.frontend import expose_substitution
from launch.launch_introspector import format_substitutions
from launch.substitutions import SubstitutionFailure
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from launch import SomeSubstitutionsType, Substitution
from launch_ros.substitutions.find_package import FindPackagePrefix

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


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
        return (f'ExecInPkg(pkg={format_substitutions(self.package)}, '
                f'exec={format_substitutions(self.executable)})')
