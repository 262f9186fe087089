"""Parser: the XML front end (`<launch>...</launch>`), from a path or an open stream."""

from __future__ import annotations

import xml.etree.ElementTree as ElementTree
from typing import IO, Any

from launch import frontend
from launch_xml.entity import Entity


class Parser(frontend.Parser):
    @classmethod
    def load(cls, file: str | IO[Any]) -> tuple[Entity, Parser]:
        return Entity(ElementTree.parse(file).getroot()), cls()

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        return {'launch.xml', 'xml', 'launch'}
