"""NotEqualsSubstitution: `$(not-equals a b)`, the opposite of EqualsSubstitution."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.frontend.expose import expose_substitution
from launch.substitutions.equals_substitution import EqualsSubstitution

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


@expose_substitution('not-equals')
class NotEqualsSubstitution(EqualsSubstitution):
    def perform(self, context: LaunchContext) -> str:
        return 'false' if super().perform(context) == 'true' else 'true'
