"""The remapping types of launch_ros' public API, under upstream's names."""

from collections.abc import Iterable

from launch.some_substitutions_type import SomeSubstitutionsType
from launch.substitution import Substitution

# ('chatter', 'talk'), as `Node(remappings=[...])` and `SetRemap` take them.
SomeRemapRule = tuple[SomeSubstitutionsType, SomeSubstitutionsType]
SomeRemapRules = Iterable[SomeRemapRule]
# The same once normalize_remap_rules() has turned both sides into substitution lists.
RemapRule = tuple[tuple[Substitution, ...], tuple[Substitution, ...]]
RemapRules = Iterable[RemapRule]
