"""visit_all_entities_and_collect_futures(): visit depth first, keep (entity, future) pairs."""

from __future__ import annotations

import asyncio
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.launch_description_entity import LaunchDescriptionEntity


def visit_all_entities_and_collect_futures(
        entity: LaunchDescriptionEntity, context: LaunchContext,
) -> list[tuple[LaunchDescriptionEntity, asyncio.Future]]:
    sub_entities = entity.visit(context)
    pairs: list[tuple[LaunchDescriptionEntity, asyncio.Future]] = []
    # The entity's own future is taken before its sub-entities are visited (upstream's order).
    future = entity.get_asyncio_future()
    if future is not None:
        pairs.append((entity, future))
    for sub_entity in sub_entities or []:
        pairs.extend(visit_all_entities_and_collect_futures(sub_entity, context))
    return pairs
