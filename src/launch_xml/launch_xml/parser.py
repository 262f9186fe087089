"""Reads an XML launch file into launch.frontend entities: a tag per element."""

from __future__ import annotations

import xml.etree.ElementTree as ElementTree

from launch.frontend import Entity, FrontendError

from launch import frontend


def _entity(element: ElementTree.Element) -> Entity:
    return Entity(element.tag, dict(element.attrib), [_entity(child) for child in element])


class Parser(frontend.Parser):
    file_extensions = ('xml',)

    @classmethod
    def load(cls, path: str) -> Entity:
        try:
            return _entity(ElementTree.parse(path).getroot())
        except ElementTree.ParseError as error:
            raise FrontendError(f'invalid XML: {error}') from None
