"""The substitutions launch files use most: configurations, paths, environment, expressions."""

from __future__ import annotations

import importlib
import math
import os
import shlex
import shutil
import subprocess
import uuid
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.frontend.expose import expose_substitution, one_argument
from launch.substitution import (
    SomeSubstitutionsType,
    Substitution,
    describe,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from launch.substitutions.substitution_failure import SubstitutionFailure

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext


@expose_substitution('var')
class LaunchConfiguration(Substitution):
    """The value of a launch configuration (a launch argument, or one set by an action)."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        if len(data) == 2:
            return cls, {'variable_name': data[0], 'default': data[1]}
        return cls, {'variable_name': one_argument('var', data)}

    def __init__(self, variable_name: SomeSubstitutionsType,
                 *, default: SomeSubstitutionsType | None = None) -> None:
        self.variable_name = normalize_to_list_of_substitutions(variable_name)
        self.default = None if default is None else normalize_to_list_of_substitutions(default)

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.variable_name)
        if name in context.launch_configurations:
            value = context.launch_configurations[name]
            if isinstance(value, str):
                return value
            return perform_substitutions(context, normalize_to_list_of_substitutions(value))
        if self.default is None:
            raise SubstitutionFailure(f"launch configuration '{name}' does not exist")
        return perform_substitutions(context, self.default)

    def describe(self) -> str:
        return f'LaunchConfig({describe(self.variable_name)})'


class PathJoinSubstitution(Substitution):
    """Path components joined with the platform's separator."""

    def __init__(self, substitutions: Iterable[SomeSubstitutionsType]) -> None:
        self.substitutions = [normalize_to_list_of_substitutions(part) for part in substitutions]

    def perform(self, context: LaunchContext) -> str:
        return os.path.join(*(perform_substitutions(context, part)
                              for part in self.substitutions))

    def __truediv__(self, other: SomeSubstitutionsType) -> PathJoinSubstitution:
        joined = PathJoinSubstitution([])
        joined.substitutions = [*self.substitutions, normalize_to_list_of_substitutions(other)]
        return joined

    def describe(self) -> str:
        return 'PathJoin(' + ', '.join(describe(part) for part in self.substitutions) + ')'


@expose_substitution('env')
class EnvironmentVariable(Substitution):
    """An environment variable of the launched processes' environment."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {'name': data[0], 'default_value': data[1] if len(data) > 1 else None}

    def __init__(self, name: SomeSubstitutionsType,
                 *, default_value: SomeSubstitutionsType | None = None) -> None:
        self.name = normalize_to_list_of_substitutions(name)
        self.default_value = (None if default_value is None
                              else normalize_to_list_of_substitutions(default_value))

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.name)
        value = context.environment.get(name)
        if value is not None:
            return value
        if self.default_value is None:
            raise SubstitutionFailure(f"environment variable '{name}' does not exist")
        return perform_substitutions(context, self.default_value)

    def describe(self) -> str:
        return f'EnvVar({describe(self.name)})'


@expose_substitution('find-exec')
class FindExecutable(Substitution):
    """The full path of an executable found on the PATH."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {'name': one_argument('find-exec', data)}

    def __init__(self, *, name: SomeSubstitutionsType) -> None:
        self.name = normalize_to_list_of_substitutions(name)

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.name)
        found = shutil.which(name, path=context.environment.get('PATH'))
        if found is None:
            raise SubstitutionFailure(f"executable '{name}' not found on the PATH")
        return found

    def describe(self) -> str:
        return f'FindExec({describe(self.name)})'


@expose_substitution('eval')
class PythonExpression(Substitution):
    """The text of a Python expression's value (modules: math by default)."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {'expression': one_argument('eval', data)}

    def __init__(self, expression: SomeSubstitutionsType,
                 python_modules: SomeSubstitutionsType | Iterable[Any] = ('math',)) -> None:
        self.expression = normalize_to_list_of_substitutions(expression)
        modules = [python_modules] if isinstance(python_modules, (str, Substitution)) \
            else list(python_modules)
        self.python_modules = [normalize_to_list_of_substitutions(m) for m in modules]

    def perform(self, context: LaunchContext) -> str:
        namespace: dict[str, Any] = {}
        for module_subs in self.python_modules:
            name = perform_substitutions(context, module_subs)
            namespace[name] = importlib.import_module(name)
            if name == 'math':
                # Upstream lets expressions say `pi` as well as `math.pi`.
                namespace.update({k: v for k, v in vars(math).items() if not k.startswith('_')})
        expression = perform_substitutions(context, self.expression)
        try:
            return str(eval(expression, namespace))
        except Exception as error:
            raise SubstitutionFailure(
                f"PythonExpression '{expression}' failed: {type(error).__name__}: {error}"
            ) from None

    def describe(self) -> str:
        return f'PythonExpr({describe(self.expression)})'


class LocalSubstitution(Substitution):
    """A local of the launch context, e.g. `event.reason` inside an event handler."""

    def __init__(self, expression: str, description: str | None = None) -> None:
        self.expression = expression
        self.description = description

    def perform(self, context: LaunchContext) -> str:
        try:
            return str(eval(self.expression, {}, context.get_locals_as_dict()))
        except Exception as error:
            raise SubstitutionFailure(
                f"local '{self.expression}' is not available here ({error})") from None

    def describe(self) -> str:
        return self.description or f'LocalVar({self.expression!r})'


class _LaunchFileLocal(Substitution):
    """A local the include of a launch file sets (its path or its directory)."""

    key = ''

    def perform(self, context: LaunchContext) -> str:
        value = context.get_locals_as_dict().get(self.key)
        if value is None:
            raise SubstitutionFailure(f'{type(self).__name__} used outside of a launch file')
        return value


@expose_substitution('dirname')
class ThisLaunchFileDir(_LaunchFileLocal):
    """The directory of the launch file being loaded."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {}

    key = 'current_launch_file_directory'


@expose_substitution('filename')
class ThisLaunchFile(_LaunchFileLocal):
    """The path of the launch file being loaded."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {}

    key = 'current_launch_file_path'


@expose_substitution('command')
class Command(Substitution):
    """The standard output of a command run when the substitution is performed."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {'command': data[0], 'on_stderr': data[1] if len(data) > 1 else 'fail'}

    def __init__(self, command: SomeSubstitutionsType, *,
                 on_stderr: SomeSubstitutionsType = 'fail') -> None:
        self.command = normalize_to_list_of_substitutions(command)
        self.on_stderr = normalize_to_list_of_substitutions(on_stderr)

    def perform(self, context: LaunchContext) -> str:
        command = perform_substitutions(context, self.command)
        try:
            result = subprocess.run(shlex.split(command), capture_output=True, text=True,
                                    env=context.environment, timeout=60)
        except (OSError, subprocess.TimeoutExpired) as error:
            raise SubstitutionFailure(f"command '{command}' failed: {error}") from None
        if result.returncode != 0:
            raise SubstitutionFailure(f"executed command failed. Command: {command}\n"
                                      f"Captured stderr output: {result.stderr}")
        policy = perform_substitutions(context, self.on_stderr)
        if result.stderr and policy == 'fail':
            raise SubstitutionFailure(f'executed command showed stderr output. Command: '
                                      f'{command}\nCaptured stderr output: {result.stderr}')
        return result.stdout


@expose_substitution('anon')
class AnonName(Substitution):
    """A name made unique for this launch, the same text for the same name."""

    @classmethod
    def parse(cls, data: list[list[Substitution]]) -> tuple[type, dict[str, Any]]:
        return cls, {'name': one_argument('anon', data)}

    def __init__(self, name: SomeSubstitutionsType) -> None:
        self.name = normalize_to_list_of_substitutions(name)

    def perform(self, context: LaunchContext) -> str:
        name = perform_substitutions(context, self.name)
        names = context.launch_configurations.setdefault('anon', {})
        if not isinstance(names, dict):
            names = {}
        if name not in names:
            names[name] = f'{name}_{uuid.uuid4().hex[:12]}'
        return names[name]
