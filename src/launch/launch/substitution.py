"""Substitution: a value worked out when the launch runs."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


class Substitution:
    """Base class: `perform(context)` returns the text this stands for."""

    def perform(self, context: LaunchContext) -> str:
        raise NotImplementedError()

    def describe(self) -> str:
        return f'{type(self).__name__}()'


def describe(subs: list[Substitution]) -> str:
    """A list of substitutions as text for --print and error messages."""
    return ' + '.join(sub.describe() for sub in subs)


def __getattr__(name: str) -> Any:
    # Older spellings this workspace used: the helpers now live in launch.utilities and
    # TextSubstitution in launch.substitutions (imported late: they import this module).
    if name in ('normalize_to_list_of_substitutions', 'perform_substitutions'):
        import launch.utilities
        return getattr(launch.utilities, name)
    if name == 'TextSubstitution':
        from launch.substitutions.text_substitution import TextSubstitution
        return TextSubstitution
    if name in ('SomeSubstitutionsType', 'SomeSubstitutionsType_types_tuple'):
        import launch.some_substitutions_type
        return getattr(launch.some_substitutions_type, name)
    raise AttributeError(name)
