"""normalize_to_list_of_entities(): entities and lists of entities, flattened once."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launch.launch_description_entity import LaunchDescriptionEntity


def normalize_to_list_of_entities(entities: Iterable[Any]) -> list[LaunchDescriptionEntity]:
    flat: list[LaunchDescriptionEntity] = []
    for entity in entities:
        if isinstance(entity, LaunchDescriptionEntity):
            flat.append(entity)
        else:
            flat.extend(entity)
    return flat
