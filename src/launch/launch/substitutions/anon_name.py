"""AnonName: `$(anon name)`, a name made unique for this launch, the same for the same name."""

from __future__ import annotations

import os
import random
import re
import socket
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.substitution import Substitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_substitution('anon')
class AnonName(Substitution):
    def __init__(self, name: SomeSubstitutionsType) -> None:
        self.__name = normalize_to_list_of_substitutions(name)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if len(data) != 1:
            raise TypeError('anon substitution expects 1 argument')
        return cls, {'name': data[0]}

    @property
    def name(self) -> list[Substitution]:
        return self.__name

    def describe(self) -> str:
        return 'AnonName({})'.format(' + '.join(sub.describe() for sub in self.name))

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.name)
        # Kept among the launch configurations, so a group scope forgets it as upstream's does.
        key = 'anon' + name
        if key not in context.launch_configurations:
            context.launch_configurations[key] = self.compute_name(name)
        return context.launch_configurations[key]

    def compute_name(self, id_value: str) -> str:
        raw = (f'{id_value}_{socket.gethostname()}_{os.getpid()}_'
               f'{random.randint(0, sys.maxsize)}')
        return re.sub(r'[.:-]', '_', raw)
