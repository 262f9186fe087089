"""FileContent: `$(file-content path)`, the text of a file."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.substitution import Substitution
from launch.substitutions.substitution_failure import SubstitutionFailure
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_substitution('file-content')
class FileContent(Substitution):
    def __init__(self, path: SomeSubstitutionsType) -> None:
        self.__path = normalize_to_list_of_substitutions(path)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if len(data) != 1:
            raise AttributeError('file content substitutions expect 1 argument')
        return cls, {'path': data[0]}

    @property
    def path(self) -> list[Substitution]:
        return self.__path

    def describe(self) -> str:
        return 'FileContent({})'.format(', '.join(sub.describe() for sub in self.path))

    def perform(self, context: LaunchContext) -> str:
        path = perform_substitutions(context, self.path)
        try:
            with open(path, encoding='utf-8') as file:
                return file.read()
        except FileNotFoundError:
            raise SubstitutionFailure(f'File not found: {path}') from None
