"""Command: `$(command 'cmd args' [on_stderr])`, the standard output of a command."""

from __future__ import annotations

import shlex
import subprocess
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution
from launch.logging import get_logger
from launch.substitution import Substitution
from launch.substitutions.substitution_failure import SubstitutionFailure
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType

_ON_STDERR = ('fail', 'ignore', 'warn', 'capture')


@expose_substitution('command')
class Command(Substitution):
    def __init__(self, command: SomeSubstitutionsType, *,
                 on_stderr: SomeSubstitutionsType = 'fail') -> None:
        self.__command = normalize_to_list_of_substitutions(command)
        self.__on_stderr = normalize_to_list_of_substitutions(on_stderr)

    @classmethod
    def parse(cls, data: Sequence[Any]) -> tuple[type, dict[str, Any]]:
        if not 1 <= len(data) <= 2:
            raise ValueError('command substitution expects 1 or 2 arguments')
        kwargs = {'command': data[0]}
        if len(data) == 2:
            kwargs['on_stderr'] = data[1]
        return cls, kwargs

    @property
    def command(self) -> list[Substitution]:
        return self.__command

    @property
    def on_stderr(self) -> list[Substitution]:
        return self.__on_stderr

    def describe(self) -> str:
        return 'Command({})'.format(' + '.join(sub.describe() for sub in self.command))

    def perform(self, context: LaunchContext) -> str:
        text = perform_substitutions(context, self.command)
        on_stderr = perform_substitutions(context, self.on_stderr)
        if on_stderr not in _ON_STDERR:
            raise SubstitutionFailure(
                "expected 'on_stderr' to be one of: 'fail', 'ignore', 'warn' or 'capture'")
        stderr = subprocess.STDOUT if on_stderr == 'capture' else subprocess.PIPE
        try:
            result = subprocess.run(shlex.split(text), stdout=subprocess.PIPE, stderr=stderr,
                                    text=True)
        except FileNotFoundError as error:
            raise SubstitutionFailure(f'file not found: {error}') from None
        if result.returncode != 0:
            message = f'executed command failed. Command: {text}'
            if result.stderr:
                message += f'\nCaptured stderr output: {result.stderr}'
            raise SubstitutionFailure(message)
        if result.stderr:
            message = (f'executed command showed stderr output. Command: {text}\n'
                       f'Captured stderr output:\n{result.stderr}')
            if on_stderr == 'fail':
                raise SubstitutionFailure(message)
            if on_stderr == 'warn':
                get_logger().warning(message)
        return result.stdout
