"""PathJoinSubstitution: path components joined with the platform's separator."""

from __future__ import annotations

import os
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.substitution import Substitution
from launch.utilities import normalize_to_list_of_substitutions

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class PathJoinSubstitution(Substitution):
    def __init__(self, substitutions: Iterable[str | Substitution]) -> None:
        self.__substitutions = normalize_to_list_of_substitutions(substitutions)

    @property
    def substitutions(self) -> list[Substitution]:
        return self.__substitutions

    def describe(self) -> str:
        return f"PathJoin('{' + '.join(s.describe() for s in self.substitutions)}')"

    def perform(self, context: LaunchContext) -> str:
        return os.path.join(*(sub.perform(context) for sub in self.__substitutions))

    def __truediv__(self, additional_path: Any) -> PathJoinSubstitution:
        """`PathJoinSubstitution([a]) / 'b'`, as pathlib's operator."""
        return PathJoinSubstitution([*self.__substitutions,
                                     *normalize_to_list_of_substitutions(additional_path)])
