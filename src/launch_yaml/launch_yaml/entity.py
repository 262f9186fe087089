"""Entity: a YAML mapping (or list of children) as a launch.frontend entity.

An action is a one-key mapping `- tag: {attributes...}`; its children are under `children`
(or the value is the list of children itself).
"""

from __future__ import annotations

from typing import Any

from launch.frontend import Entity as BaseEntity
from launch.frontend.type_utils import check_is_list_entity
from launch.utilities.type_utils import is_instance_of


class Entity(BaseEntity):
    def __init__(self, element: Any, type_name: str | None = None, *,
                 parent: Entity | None = None) -> None:
        self.__type_name = type_name
        self.__element = element
        self.__parent = parent
        self.__read_keys: set[str] = set()
        self.__children_called = False

    @property
    def type_name(self) -> str:
        return self.__type_name or ''

    @property
    def parent(self) -> Entity | None:
        return self.__parent

    @property
    def children(self) -> list[Entity]:
        self.__children_called = True
        if isinstance(self.__element, dict):
            # A mapping without `children` has none (upstream raises; an action that looks
            # for nested tags of its own must not fail on a childless one).
            self.__read_keys.add('children')
            children = self.__element.get('children') or []
        elif isinstance(self.__element, list):
            children = self.__element
        else:
            raise TypeError(f'Expected a dict or list, got {type(self.__element)}:\n---\n'
                            f'{self.__element}\n---')
        entities = []
        for child in children:
            if not isinstance(child, dict) or len(child) != 1:
                raise RuntimeError('Subentities must be a dictionary with only one key, which '
                                   'is the entity type')
            ((type_name, body),) = child.items()
            entities.append(Entity(body, type_name, parent=self))
        return entities

    def assert_entity_completely_parsed(self) -> None:
        if isinstance(self.__element, list):
            if not self.__children_called:
                raise ValueError(f'Unexpected nested entity(ies) found in '
                                 f'`{self.__type_name}`: {self.__element}')
            return
        unread = set(self.__element or {}) - self.__read_keys
        if unread:
            raise ValueError(f'Unexpected key(s) found in `{self.__type_name}`: {unread}')

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False,
                 can_be_str: bool = True) -> Any:
        element = self.__element if isinstance(self.__element, dict) else {}
        if name not in element:
            if optional:
                return None
            raise AttributeError(f"Can not find attribute '{name}' in Entity "
                                 f"'{self.type_name}'")
        self.__read_keys.add(name)
        data = element[name]
        if check_is_list_entity(data_type):
            if isinstance(data, list) and data and isinstance(data[0], dict):
                return [Entity(child, name, parent=self) for child in data]
            raise TypeError(f"Attribute '{name}' of Entity '{self.type_name}' expected to be a "
                            'list of dictionaries.')
        if data_type is not None and not is_instance_of(data, data_type, can_be_str=can_be_str):
            raise TypeError(f"Attribute '{name}' of Entity '{self.type_name}' expected to be of "
                            f"type '{data_type}', got '{type(data)}'")
        return data
