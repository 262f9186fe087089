"""LaunchDescriptionEntity: anything a launch description holds."""

from __future__ import annotations

import asyncio
from collections.abc import Iterable
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class LaunchDescriptionEntity:
    def describe(self) -> str:
        raise NotImplementedError()

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        """Entities this one always brings (for introspection: argument lists, --print)."""
        return []

    def describe_conditional_sub_entities(
            self) -> list[tuple[str, Iterable[LaunchDescriptionEntity]]]:
        """(why, entities) this one may bring, depending on something known only at run time."""
        return []

    def visit(self, context: LaunchContext) -> list[LaunchDescriptionEntity] | None:
        """Do this entity's work; return the entities to visit next."""
        return None

    def get_asyncio_future(self) -> asyncio.Future | None:
        """A future the launch waits for before it is idle (a process, a timer), or None."""
        return None
