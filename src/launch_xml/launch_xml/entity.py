"""Entity: an XML element as a launch.frontend entity (attributes, nested tags)."""

from __future__ import annotations

import xml.etree.ElementTree as ElementTree
from typing import Any

from launch.frontend import Entity as BaseEntity
from launch.frontend.type_utils import check_is_list_entity
from launch.utilities.type_utils import get_typed_value


class Entity(BaseEntity):
    def __init__(self, xml_element: ElementTree.Element, *, parent: Entity | None = None
                 ) -> None:
        self.__element = xml_element
        self.__parent = parent
        self.__read_attributes: set[str] = set()
        self.__read_children: set[str] = set()

    @property
    def type_name(self) -> str:
        return self.__element.tag

    @property
    def parent(self) -> Entity | None:
        return self.__parent

    @property
    def children(self) -> list[Entity]:
        self.__read_children = {child.tag for child in self.__element}
        return [Entity(child, parent=self) for child in self.__element]

    def assert_entity_completely_parsed(self) -> None:
        unread_tags = {child.tag for child in self.__element} - self.__read_children
        if unread_tags:
            raise ValueError(f'Unexpected nested tag(s) found in `{self.__element.tag}`: '
                             f'{unread_tags}')
        unread = set(self.__element.attrib) - self.__read_attributes
        if unread:
            raise ValueError(f'Unexpected attribute(s) found in `{self.__element.tag}`: '
                             f'{unread}')

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False,
                 can_be_str: bool = True) -> Any:
        """An attribute as data_type; `name-sep="x"` splits it into a list at each x."""
        missing = AttributeError(f"Attribute '{name}' of type '{data_type}' not found in "
                                 f"Entity '{self.type_name}'")
        if check_is_list_entity(data_type):
            nested = [child for child in self.__element if child.tag == name]
            if not nested:
                if optional:
                    return None
                raise missing
            self.__read_children.add(name)
            return [Entity(child, parent=self) for child in nested]
        if name not in self.__element.attrib:
            if optional:
                return None
            raise missing
        self.__read_attributes.add(name)
        value: Any = self.__element.attrib[name]
        separator = self.__element.attrib.get(name + '-sep')
        if separator is not None:
            self.__read_attributes.add(name + '-sep')
            value = value.split(separator)
        try:
            return get_typed_value(value, data_type, can_be_str=can_be_str)
        except ValueError:
            raise TypeError(f"Attribute '{name}' of Entity '{self.type_name}' expected to be of "
                            f"type '{data_type}'.'{value}' can not be converted to one of those "
                            'types') from None
