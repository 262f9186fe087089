"""Entity: one tag of a launch file, its attributes and children, whatever the file format."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launch.substitution import Substitution


class FrontendError(ValueError):
    """A launch file asks for something wrong or unsupported; the text names it."""


class Entity:
    """Built by a front end (launch_xml, launch_yaml); read by the actions' `parse` methods.

    Every attribute read is remembered, so an attribute no parser read is reported by name
    instead of being ignored.
    """

    def __init__(self, tag: str, attributes: dict[str, Any], children: list[Entity]) -> None:
        self.tag = tag.replace('-', '_')
        self.attributes = attributes
        self.children = children
        self._used: set[str] = set()

    @property
    def type_name(self) -> str:  # upstream's name for the tag
        return self.tag

    def get(self, name: str, default: Any = None, required: bool = False) -> Any:
        self._used.add(name)
        if name in self.attributes:
            return self.attributes[name]
        if required:
            raise FrontendError(f"<{self.tag}> needs the attribute '{name}'")
        return default

    def get_bool(self, name: str, default: bool) -> bool:
        value = self.get(name)
        if value is None:
            return default
        if isinstance(value, bool):
            return value
        if str(value).lower() in ('true', '1'):
            return True
        if str(value).lower() in ('false', '0'):
            return False
        raise FrontendError(f"<{self.tag} {name}=...> must be true or false, got '{value}'")

    def get_substitutions(self, name: str, required: bool = False
                          ) -> list[Substitution] | None:
        """The attribute with its `$(...)` substitutions parsed, None when absent."""
        from launch.frontend.parse_substitution import parse_substitutions
        value = self.get(name, required=required)
        return None if value is None else parse_substitutions(value)

    def get_words(self, name: str) -> list[list[Substitution]] | None:
        """A command-line attribute (`args`, `cmd`) split into words, None when absent."""
        from launch.frontend.parse_substitution import parse_substitutions, split_command_line
        value = self.get(name)
        return None if value is None else split_command_line(parse_substitutions(value))

    def children_of(self, tag: str) -> list[Entity]:
        return [child for child in self.children if child.tag == tag]

    def check_all_used(self) -> None:
        unused = sorted(set(self.attributes) - self._used)
        if unused:
            raise FrontendError(f"<{self.tag}>: attribute '{unused[0]}' is not supported "
                                'by this launch (see docs/launch.md)')
