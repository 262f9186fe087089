"""Substitution: a value worked out when the launch runs, and the helpers around it."""

from __future__ import annotations

import pathlib
from collections.abc import Iterable
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class Substitution:
    """Base class: `perform(context)` returns the text this stands for."""

    def perform(self, context: LaunchContext) -> str:
        raise NotImplementedError(type(self).__name__)

    def describe(self) -> str:
        return repr(self)


class TextSubstitution(Substitution):
    """Plain text."""

    def __init__(self, *, text: str) -> None:
        self.text = text

    def perform(self, context: LaunchContext) -> str:
        return self.text

    def describe(self) -> str:
        return repr(self.text)


SomeSubstitutionsType = (str | pathlib.PurePath | Substitution
                         | Iterable[str | pathlib.PurePath | Substitution])
SomeSubstitutionsType_types_tuple = (str, pathlib.PurePath, Substitution)


def normalize_to_list_of_substitutions(subs: SomeSubstitutionsType) -> list[Substitution]:
    """Text, a path, a substitution or an iterable of them, as a list of substitutions."""
    if isinstance(subs, (str, pathlib.PurePath, Substitution, int, float)):
        subs = [subs]
    result: list[Substitution] = []
    for item in subs:
        if isinstance(item, Substitution):
            result.append(item)
        elif isinstance(item, (str, pathlib.PurePath, int, float)):
            # Numbers are accepted for convenience (upstream insists on text).
            result.append(TextSubstitution(text=str(item)))
        else:
            raise TypeError(f'expected text or a Substitution, got {type(item).__name__}: '
                            f'{item!r}')
    return result


def perform_substitutions(context: LaunchContext, subs: list[Substitution]) -> str:
    return ''.join(sub.perform(context) for sub in subs)


def describe(subs: list[Substitution]) -> str:
    return ' + '.join(sub.describe() for sub in subs)
