"""Parser: turns an Entity tree into a LaunchDescription; the base of every front end.

A front end (launch_xml, launch_yaml) subclasses Parser, reads its file format into Entity
trees in `load`, and registers itself in the `launch.frontend.parser` entry point group.
Tags come from the actions' own registrations: launch's, and those of every package in the
`launch.frontend.launch_extension` group (launch_ros), imported on first use.
"""

from __future__ import annotations

from importlib.metadata import entry_points
from typing import TYPE_CHECKING

from launch.frontend.entity import Entity, FrontendError
from launch.frontend.expose import instantiate_action
from launch.frontend.parse_substitution import parse_substitutions

if TYPE_CHECKING:
    from launch.action import Action
    from launch.launch_description import LaunchDescription
    from launch.substitution import Substitution

PARSER_GROUP = 'launch.frontend.parser'
EXTENSION_GROUP = 'launch.frontend.launch_extension'


class Parser:
    file_extensions: tuple[str, ...] = ()  # the file name endings this front end reads

    _extensions_loaded = False
    _implementations: dict[str, type[Parser]] | None = None

    @classmethod
    def load(cls, path: str) -> Entity:
        """The file's root Entity (a front end's job)."""
        raise NotImplementedError(f'{cls.__name__} reads no file format')

    @classmethod
    def may_parse(cls, path: str) -> bool:
        return path.endswith(tuple('.' + extension for extension in cls.file_extensions))

    @classmethod
    def load_launch_extensions(cls) -> None:
        """Import what registers tags: launch's actions and substitutions, and extensions."""
        if Parser._extensions_loaded:
            return
        import launch.actions
        import launch.substitutions  # noqa: F401
        for entry_point in entry_points(group=EXTENSION_GROUP):
            entry_point.load()  # a broken extension fails the launch file loudly
        Parser._extensions_loaded = True

    @classmethod
    def implementations(cls) -> dict[str, type[Parser]]:
        """The installed front ends by name ('xml', 'yaml')."""
        if Parser._implementations is None:
            Parser._implementations = {entry_point.name: entry_point.load() for entry_point
                                       in sorted(entry_points(group=PARSER_GROUP),
                                                 key=lambda e: e.name)}
        return Parser._implementations

    def parse_action(self, entity: Entity) -> Action:
        self.load_launch_extensions()
        return instantiate_action(entity, self)

    def parse_children(self, entity: Entity) -> list[Action]:
        return [self.parse_action(child) for child in entity.children]

    def parse_substitution(self, value: object) -> list[Substitution]:
        self.load_launch_extensions()
        return parse_substitutions(value)

    def parse_description(self, root: Entity) -> LaunchDescription:
        from launch.launch_description import LaunchDescription
        if root.tag != 'launch':
            raise FrontendError(f'the root element must be <launch>, got <{root.tag}>')
        return LaunchDescription(self.parse_children(root))


def load_frontend_file(path: str, kind: str | None = None) -> LaunchDescription:
    """The LaunchDescription of an XML or YAML launch file (`kind` 'xml'/'yaml', or by name)."""
    front_ends = Parser.implementations()
    if kind is not None:
        front_end = front_ends.get(kind)
    else:
        front_end = next((p for p in front_ends.values() if p.may_parse(path)), None)
    if front_end is None:
        raise FrontendError(f'no launch front end reads {kind or path} files (installed: '
                            f"{', '.join(front_ends) or 'none'}; launch_xml and launch_yaml "
                            'provide xml and yaml)')
    return front_end().parse_description(front_end.load(path))
