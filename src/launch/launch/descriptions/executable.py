"""Executable: a command line, its name, working directory and environment.

`prepare()` performs the substitutions once, when the action runs: the final command (with
the `launch-prefix` launch configuration in front, when `launch-prefix-filter` matches the
executable), the unique name `<name>-<N>` (N counts every process of this launch), and the
environment (the launch's own, or `env`, plus `additional_env`).
"""

from __future__ import annotations

import itertools
import os
import re
import shlex
import threading
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.substitutions.launch_configuration import LaunchConfiguration
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType
    from launch.substitution import Substitution

_counter_lock = threading.Lock()
_counter = itertools.count(1)


def _pairs(mapping: dict[Any, Any] | None) -> list[tuple[list, list]] | None:
    if mapping is None:
        return None
    return [(normalize_to_list_of_substitutions(key), normalize_to_list_of_substitutions(value))
            for key, value in mapping.items()]


class Executable:
    def __init__(self, *, cmd: Iterable[SomeSubstitutionsType],
                 prefix: SomeSubstitutionsType | None = None,
                 name: SomeSubstitutionsType | None = None,
                 cwd: SomeSubstitutionsType | None = None,
                 env: dict[SomeSubstitutionsType, SomeSubstitutionsType] | None = None,
                 additional_env: dict[SomeSubstitutionsType, SomeSubstitutionsType] | None = None,
                 arguments: Iterable[SomeSubstitutionsType] | None = None) -> None:
        if isinstance(cmd, (str, os.PathLike)):
            cmd = [cmd]
        self.__cmd = [normalize_to_list_of_substitutions(part) for part in cmd]
        self.__cmd += [normalize_to_list_of_substitutions(part) for part in arguments or []]
        self.__prefix = normalize_to_list_of_substitutions(
            LaunchConfiguration('launch-prefix', default='') if prefix is None else prefix)
        # The launch-wide prefix may be limited to some executables; a given prefix is not.
        self.__prefix_filter = normalize_to_list_of_substitutions(
            LaunchConfiguration('launch-prefix-filter', default='')) if prefix is None else None
        self.__name = None if name is None else normalize_to_list_of_substitutions(name)
        self.__cwd = None if cwd is None else normalize_to_list_of_substitutions(cwd)
        self.__env = _pairs(env)
        self.__additional_env = _pairs(additional_env)
        self.__arguments = arguments
        self.__final_cmd: list[str] | None = None
        self.__final_cwd: str | None = None
        self.__final_env: dict[str, str] | None = None
        self.__final_name: str | None = None

    @property
    def name(self) -> list[Substitution] | None:
        return self.__name

    @property
    def prefix(self) -> list[Substitution]:
        return self.__prefix

    @property
    def cmd(self) -> list[list[Substitution]]:
        return self.__cmd

    @property
    def cwd(self) -> list[Substitution] | None:
        return self.__cwd

    @property
    def env(self) -> list[tuple[list, list]] | None:
        return self.__env

    @property
    def additional_env(self) -> list[tuple[list, list]] | None:
        return self.__additional_env

    @property
    def arguments(self) -> Iterable[Any] | None:
        return self.__arguments

    @property
    def final_name(self) -> str | None:
        return self.__final_name

    @property
    def final_cmd(self) -> list[str] | None:
        return self.__final_cmd

    @property
    def final_cwd(self) -> str | None:
        return self.__final_cwd

    @property
    def final_env(self) -> dict[str, str] | None:
        return self.__final_env

    def prepare(self, context: LaunchContext, action: Any) -> None:
        cmd = [perform_substitutions(context, part) for part in self.__cmd]
        apply_prefix = True
        if self.__prefix_filter is not None:
            pattern = perform_substitutions(context, self.__prefix_filter)
            apply_prefix = re.match(pattern, os.path.basename(cmd[0])) is not None
        if apply_prefix:
            cmd = shlex.split(perform_substitutions(context, self.__prefix)) + cmd
        self.__final_cmd = cmd
        base = (os.path.basename(cmd[0]) if self.__name is None
                else perform_substitutions(context, self.__name))
        with _counter_lock:
            self.__final_name = f'{base}-{next(_counter)}'
        self.__final_cwd = (None if self.__cwd is None
                            else perform_substitutions(context, self.__cwd))
        if self.__env is not None:
            env = {perform_substitutions(context, key): perform_substitutions(context, value)
                   for key, value in self.__env}
        else:
            env = dict(context.environment)
        for key, value in self.__additional_env or []:
            env[perform_substitutions(context, key)] = perform_substitutions(context, value)
        self.__final_env = env
