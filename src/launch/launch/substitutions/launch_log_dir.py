"""LaunchLogDir: `$(log_dir)` / `$(launch_log_dir)`, this launch's log directory."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.logging import launch_config
from launch.substitution import Substitution

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


@expose_substitution('launch_log_dir')
@expose_substitution('log_dir')
class LaunchLogDir(Substitution):
    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if len(data) != 0:
            raise TypeError("launch_log_dir/log_dir substitution doesn't expect arguments")
        return cls, {}

    def describe(self) -> str:
        return 'LaunchLogDir()'

    def perform(self, context: LaunchContext) -> str:
        return launch_config.log_dir
