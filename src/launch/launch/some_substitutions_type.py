"""SomeSubstitutionsType: text, a path, a substitution, or an iterable of them."""

import pathlib
from collections.abc import Iterable

from launch.substitution import Substitution

SomeSubstitutionsType = (str | pathlib.PurePath | Substitution
                         | Iterable[str | pathlib.PurePath | Substitution])
SomeSubstitutionsType_types_tuple = (str, pathlib.PurePath, Substitution, Iterable)
