"""UnlessCondition: true when its expression is 'false' or '0'."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.conditions.if_condition import IfCondition

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class UnlessCondition(IfCondition):
    def _predicate_func(self, context: LaunchContext) -> bool:
        return not super()._predicate_func(context)
