"""Entity: one tag of a launch file, whatever the file format (launch_xml, launch_yaml).

A front end implements upstream's interface: `type_name`, `parent`, `children`,
`get_attr(name, data_type=str, optional=False, can_be_str=True)` and
`assert_entity_completely_parsed()`. The helpers below it (`get`, `get_substitutions`, ...)
are this workspace's shorthands built on `get_attr`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launch.substitution import Substitution


class FrontendError(ValueError):
    """A launch file asks for something wrong or unsupported; the text names it."""


class Entity:
    @property
    def type_name(self) -> str:
        raise NotImplementedError()

    @property
    def parent(self) -> Entity | None:
        raise NotImplementedError()

    @property
    def children(self) -> list[Entity]:
        raise NotImplementedError()

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False,
                 can_be_str: bool = True) -> Any:
        """An attribute as `data_type` (List[Entity]: the nested entities called `name`)."""
        raise NotImplementedError()

    def assert_entity_completely_parsed(self) -> None:
        """Raise when an attribute or nested tag was never read (a typo must not pass)."""
        raise NotImplementedError()

    # -- shorthands --------------------------------------------------------------------------
    @property
    def tag(self) -> str:
        return self.type_name.replace('-', '_')

    def get(self, name: str, default: Any = None, required: bool = False) -> Any:
        """The attribute as written (text, or a YAML scalar), `default` when absent."""
        try:
            value = self.get_attr(name, data_type=str, optional=True)
        except TypeError:  # a YAML number, bool or list
            value = self.get_attr(name, data_type=None, optional=True)
        if value is None:
            if required:
                raise FrontendError(f"<{self.type_name}> needs the attribute '{name}'")
            return default
        return value

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
        raise FrontendError(f"<{self.type_name} {name}=...> must be true or false, got "
                            f"'{value}'")

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
        return self.get_attr(tag, data_type=list[Entity], optional=True) or []

    def check_all_used(self) -> None:
        try:
            self.assert_entity_completely_parsed()
        except ValueError as error:
            raise FrontendError(str(error)) from None
