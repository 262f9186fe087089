"""Substitution: a value worked out when the launch runs."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class Substitution:
    """Base class: `perform(context)` returns the text this stands for."""

    def perform(self, context: LaunchContext) -> str:
        raise NotImplementedError()

    def describe(self) -> str:
        return repr(self)  # upstream's default; subclasses say more

