"""Parser: turns an Entity tree into a LaunchDescription; the base of every front end.

A front end (launch_xml, launch_yaml) subclasses Parser, reads its file format into an Entity
tree in `load(file)` (a path or an open stream) and registers itself in the
`launch.frontend.parser` entry point group. Tags come from the actions' own registrations:
launch's, and those of every package in the `launch.frontend.launch_extension` group
(launch_ros), imported on first use.
"""

from __future__ import annotations

import importlib.metadata as importlib_metadata
import itertools
import os
import warnings
from typing import IO, TYPE_CHECKING, Any

from launch.frontend.entity import Entity
from launch.frontend.expose import instantiate_action
from launch.frontend.parse_substitution import (
    parse_if_substitutions,
    parse_substitution,
    replace_escaped_characters,
)
from launch.invalid_launch_file_error import InvalidLaunchFileError

if TYPE_CHECKING:
    from launch.action import Action
    from launch.launch_description import LaunchDescription
    from launch.substitution import Substitution

PARSER_GROUP = 'launch.frontend.parser'
EXTENSION_GROUP = 'launch.frontend.launch_extension'


class InvalidFrontendLaunchFileError(InvalidLaunchFileError):
    """No front end could read the file."""


def _entry_points(group: str) -> list[Any]:
    found = importlib_metadata.entry_points()
    if hasattr(found, 'select'):
        return list(found.select(group=group))
    return list(found.get(group, []))


class Parser:
    extensions_loaded = False
    frontend_parsers: dict[str, type[Parser]] | None = None

    @classmethod
    def load_launch_extensions(cls) -> None:
        """Import what registers tags: launch's actions and substitutions, and extensions."""
        if Parser.extensions_loaded:
            return
        import launch.actions
        import launch.substitutions  # noqa: F401
        for entry_point in _entry_points(EXTENSION_GROUP):
            try:
                entry_point.load()
            except Exception as error:
                warnings.warn(f'Failed to load the launch extension: {entry_point.name}\n'
                              f'{error}', stacklevel=2)
        Parser.extensions_loaded = True

    @classmethod
    def load_parser_implementations(cls) -> None:
        if Parser.frontend_parsers is not None:
            return
        parsers = {}
        for entry_point in _entry_points(PARSER_GROUP):
            try:
                parsers[entry_point.name] = entry_point.load()
            except Exception as error:
                warnings.warn(f'Failed to load the parser extension: {entry_point.name}\n'
                              f'{error}', stacklevel=2)
        Parser.frontend_parsers = dict(sorted(parsers.items()))

    @classmethod
    def implementations(cls) -> dict[str, type[Parser]]:
        """The installed front ends by name ('xml', 'yaml')."""
        cls.load_parser_implementations()
        assert Parser.frontend_parsers is not None
        return Parser.frontend_parsers

    def parse_action(self, entity: Entity) -> Action:
        self.load_launch_extensions()
        return instantiate_action(entity, self)

    def parse_children(self, entity: Entity) -> list[Action]:
        return [self.parse_action(child) for child in entity.children]

    def parse_substitution(self, value: str) -> list[Substitution]:
        self.load_launch_extensions()
        return parse_substitution(value)

    def parse_if_substitutions(self, value: Any) -> Any:
        self.load_launch_extensions()
        return parse_if_substitutions(value)

    def escape_characters(self, value: str) -> str:
        return replace_escaped_characters(value)

    def parse_description(self, entity: Entity) -> LaunchDescription:
        from launch.launch_description import LaunchDescription
        if entity.type_name != 'launch':
            raise RuntimeError("Expected 'launch' as root tag")
        deprecated = entity.get_attr('deprecated', optional=True)
        return LaunchDescription([self.parse_action(child) for child in entity.children],
                                 deprecated_reason=deprecated)

    @classmethod
    def get_available_extensions(cls) -> list[str]:
        return list(cls.implementations())

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        """The file name endings this front end reads (a front end's own)."""
        return set()

    @classmethod
    def may_parse(cls, filename: str) -> bool:
        return any(filename.endswith('.' + ext) for ext in cls.get_file_extensions())

    @classmethod
    def is_filename_valid(cls, filename: str) -> bool:
        return any(parser.may_parse(filename) for parser in cls.implementations().values())

    @classmethod
    def get_parsers_from_filename(cls, filename: str) -> list[type[Parser]]:
        return [parser for parser in cls.implementations().values()
                if parser.may_parse(filename)]

    @classmethod
    def get_file_extensions_from_parsers(cls) -> set[str]:
        return set(itertools.chain.from_iterable(
            parser.get_file_extensions() for parser in cls.implementations().values()))

    @classmethod
    def load(cls, file: str | os.PathLike | IO[str]) -> tuple[Entity, Parser]:
        """(root Entity, the parser for it) of a file path or stream, by any front end that
        reads it: those its name suits first."""
        opened = isinstance(file, (str, bytes, os.PathLike))
        stream: IO[str] = open(file, encoding='utf-8') if opened else file
        try:
            filename = getattr(stream, 'name', '')
            filename = filename if isinstance(filename, str) else ''
            suited = cls.get_parsers_from_filename(filename)
            ordered = suited + [p for p in cls.implementations().values() if p not in suited]
            errors: list[Exception] = []
            for implementation in ordered:
                try:
                    return implementation.load(stream)
                except Exception as error:
                    errors.append(error)
                    stream.seek(0)
            extension = os.path.splitext(filename)[1][1:] if cls.is_filename_valid(
                filename) else ''
            raise InvalidFrontendLaunchFileError(extension, likely_errors=errors)
        finally:
            if opened:
                stream.close()


def load_frontend_file(path: str, kind: str | None = None) -> LaunchDescription:
    """The LaunchDescription of an XML or YAML launch file (`kind` 'xml'/'yaml', or by name)."""
    front_ends = Parser.implementations()
    if kind is not None and kind in front_ends:
        root, parser = front_ends[kind].load(path)
    else:
        root, parser = Parser.load(path)
    return parser.parse_description(root)
