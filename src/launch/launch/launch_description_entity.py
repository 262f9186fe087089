"""LaunchDescriptionEntity: anything a launch description holds."""

from __future__ import annotations

import asyncio
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class LaunchDescriptionEntity:
    def visit(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Do this entity's work; return the entities to visit next."""
        return None

    def get_asyncio_future(self) -> asyncio.Future | None:
        """A future the launch waits for before it is idle (a process, a timer), or None."""
        return None

    def describe(self) -> str:
        return f'{type(self).__name__}'

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return []

    def describe_conditional_sub_entities(self) -> list[tuple[str, list[Any]]]:
        return []
