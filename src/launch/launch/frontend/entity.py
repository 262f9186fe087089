"""Entity: one tag of a launch file, whatever the file format (launch_xml, launch_yaml).

A front end implements upstream's interface: `type_name`, `parent`, `children`,
`get_attr(name, data_type=str, optional=False, can_be_str=True)` and
`assert_entity_completely_parsed()`.
"""

from __future__ import annotations

from typing import Any


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
