"""ThisLaunchFile / ThisLaunchFileDir: `$(filename)`, `$(dirname)` of the file being read."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.substitution import Substitution
from launch.substitutions.substitution_failure import SubstitutionFailure

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


@expose_substitution('filename')
class ThisLaunchFile(Substitution):
    _local = 'current_launch_file_path'
    _tag = 'filename'

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if len(data) != 0:
            raise TypeError(f"{cls._tag} substitution doesn't expect arguments")
        return cls, {}

    def describe(self) -> str:
        return f'{type(self).__name__}()'

    def perform(self, context: LaunchContext) -> str:
        values = context.get_locals_as_dict()
        if self._local not in values:
            raise SubstitutionFailure(
                f'{type(self).__name__} used outside of a launch file (in a script)')
        return values[self._local]
