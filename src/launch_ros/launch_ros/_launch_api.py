"""launch's helpers as launch_ros uses them, at upstream's paths (`launch.utilities`, ...).

This workspace's launch is moving to upstream's module layout. Until `launch.utilities`
exists, the same helpers come from where launch kept them before (`launch.substitution`,
`launch.frontend.parse_substitution`) or, for the typed values, from launch_ros's own
`_typed_values`. Once launch has them, the fallbacks are unused (and can go).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launch import SomeSubstitutionsType_types_tuple

# What `SomeSubstitutionsType` accepts, iterables of text and substitutions included (upstream
# lists Iterable in its tuple).
SOME_SUBSTITUTIONS_TYPES = (*SomeSubstitutionsType_types_tuple, Iterable)

try:
    from launch.frontend.parse_substitution import parse_substitution
except ImportError:  # launch before its upstream layout
    from launch.frontend.parse_substitution import (  # type: ignore[no-redef]
        parse_substitutions as parse_substitution,
    )

try:
    from launch.utilities import (
        ensure_argument_type,
        normalize_to_list_of_substitutions,
        perform_substitutions,
    )
    from launch.utilities.type_utils import (
        normalize_typed_substitution,
        perform_typed_substitution,
    )
except ImportError:  # launch before its upstream layout
    from launch.substitution import (  # type: ignore[no-redef]
        normalize_to_list_of_substitutions,
        perform_substitutions,
    )

    from launch_ros._typed_values import (  # type: ignore[assignment]
        normalize_typed_substitution,
        perform_typed_substitution,
    )

    def ensure_argument_type(argument: Any, types: Any, argument_name: str,
                             caller: str | None = None) -> None:
        """TypeError naming the argument, the types allowed and the type given."""
        if isinstance(argument, types):
            return
        allowed = types if isinstance(types, tuple) else (types,)
        names = ', '.join(f"'{t.__name__}'" for t in allowed)
        where = f"'{caller}' " if caller else ''
        raise TypeError(f"{where}expected '{argument_name}' to be one of [{names}], but got "
                        f"'{type(argument).__name__}' ({argument!r})")


def describe(substitutions: list[Any]) -> str:
    """Substitutions as `describe()` shows them, joined."""
    return ' + '.join(sub.describe() for sub in substitutions)


__all__ = ['SOME_SUBSTITUTIONS_TYPES', 'describe', 'ensure_argument_type',
           'normalize_to_list_of_substitutions',
           'normalize_typed_substitution', 'parse_substitution', 'perform_substitutions',
           'perform_typed_substitution']
