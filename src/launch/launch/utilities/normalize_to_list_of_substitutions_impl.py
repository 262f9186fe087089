"""normalize_to_list_of_substitutions(): text, paths and substitutions as a list."""

from __future__ import annotations

import pathlib
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launch.substitution import Substitution


def normalize_to_list_of_substitutions(subs: Any) -> list[Substitution]:
    """Text, a path, a substitution, or an iterable of them, as a list of substitutions."""
    from launch.substitution import Substitution
    from launch.substitutions.text_substitution import TextSubstitution

    def one(item: Any) -> Substitution:
        if isinstance(item, Substitution):
            return item
        if isinstance(item, (str, pathlib.PurePath)):
            return TextSubstitution(text=str(item))
        raise TypeError(f"Failed to normalize given item of type '{type(item)}', when only "
                        "'str', 'pathlib.Path' or 'launch.Substitution' were expected.")

    if isinstance(subs, (str, pathlib.PurePath, Substitution)):
        return [one(subs)]
    if not isinstance(subs, Iterable):
        raise TypeError(f"Failed to normalize given item of type '{type(subs)}', when only "
                        "'str', 'pathlib.Path', 'launch.Substitution' or an iterable of them "
                        'were expected.')
    return [one(item) for item in subs]
