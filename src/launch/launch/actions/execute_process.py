"""ExecuteProcess: `<executable cmd=>`, runs a command line (ExecuteLocal with an Executable)."""

from __future__ import annotations

import shlex
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.actions.execute_local import ExecuteLocal
from launch.descriptions.executable import Executable
from launch.frontend.entity import Entity
from launch.frontend.expose import expose_action
from launch.substitutions.text_substitution import TextSubstitution

if TYPE_CHECKING:
    from launch.frontend.parser import Parser
    from launch.some_substitutions_type import SomeSubstitutionsType
    from launch.substitution import Substitution


def _non_negative(entity: Entity, name: str) -> float | None:
    value = entity.get_attr(name, data_type=float, optional=True)
    if value is not None and value < 0.0:
        raise ValueError(f'Attribute {name} of Entity node expected to be a non-negative value '
                         f'but got `{value}`')
    return value


@expose_action('executable')
class ExecuteProcess(ExecuteLocal):
    def __init__(self, *, cmd: Iterable[SomeSubstitutionsType],
                 prefix: SomeSubstitutionsType | None = None,
                 name: SomeSubstitutionsType | None = None,
                 cwd: SomeSubstitutionsType | None = None,
                 env: dict[SomeSubstitutionsType, SomeSubstitutionsType] | None = None,
                 additional_env: dict[SomeSubstitutionsType, SomeSubstitutionsType] | None = None,
                 **kwargs: Any) -> None:
        description = Executable(cmd=cmd, prefix=prefix, name=name, cwd=cwd, env=env,
                                 additional_env=additional_env)
        super().__init__(process_description=description, **kwargs)

    @staticmethod
    def _parse_cmdline(cmd: str, parser: Parser) -> list[list[Substitution]]:
        """A command line attribute as arguments: text split shell-like, a substitution
        kept inside the argument it touches."""
        args: list[list[Substitution]] = []
        current: list[Substitution] = []

        def close() -> None:
            nonlocal current
            args.append(current)
            current = []

        for sub in parser.parse_substitution(cmd):
            if not isinstance(sub, TextSubstitution):
                current.append(sub)
                continue
            tokens = shlex.split(sub.text)
            if not tokens:
                close()
                continue
            if sub.text[0].isspace() and current:
                close()
            current.append(TextSubstitution(text=tokens[0]))
            if len(tokens) > 1:
                close()
                args.extend([TextSubstitution(text=token)] for token in tokens[1:-1])
                current.append(TextSubstitution(text=tokens[-1]))
            if sub.text[-1].isspace():
                close()
        if current:
            args.append(current)
        return args

    @classmethod
    def parse(cls, entity: Entity, parser: Parser, ignore: list[str] | None = None
              ) -> tuple[type, dict[str, Any]]:
        """`ignore`: attributes a subclass's own parse reads (launch_ros's Node)."""
        from launch.actions.shutdown_action import Shutdown
        _, kwargs = super().parse(entity, parser)
        ignore = ignore or []

        def wanted(name: str) -> bool:
            return name not in ignore

        if wanted('cmd'):
            kwargs['cmd'] = cls._parse_cmdline(entity.get_attr('cmd'), parser)
        for key, attribute in (('cwd', 'cwd'), ('name', 'name'), ('prefix', 'launch-prefix'),
                               ('output', 'output'), ('respawn', 'respawn')):
            value = entity.get_attr(attribute, optional=True) if wanted(key) else None
            if value is not None:
                kwargs[key] = parser.parse_substitution(value)
        if wanted('on_exit'):
            on_exit = entity.get_attr('on_exit', optional=True)
            if on_exit is not None:
                if on_exit != 'shutdown':
                    raise ValueError('Attribute on_exit of Entity node expected to be shutdown '
                                     f'but got `{on_exit}`Other on_exit actions not yet '
                                     'supported')
                kwargs['on_exit'] = [Shutdown()]
        if wanted('respawn_max_retries'):
            retries = entity.get_attr('respawn_max_retries', data_type=int, optional=True)
            if retries is not None:
                kwargs['respawn_max_retries'] = retries
        if wanted('respawn_delay'):
            delay = _non_negative(entity, 'respawn_delay')
            if delay is not None:
                kwargs['respawn_delay'] = delay
        for timeout in ('sigkill_timeout', 'sigterm_timeout'):
            value = _non_negative(entity, timeout) if wanted(timeout) else None
            if value is not None:
                kwargs[timeout] = str(value)
        for flag in ('shell', 'emulate_tty'):
            value = entity.get_attr(flag, data_type=bool, optional=True) if wanted(flag) else None
            if value is not None:
                kwargs[flag] = value
        if wanted('additional_env'):
            env = entity.get_attr('env', data_type=list[Entity], optional=True)
            if env is not None:
                kwargs['additional_env'] = {
                    tuple(parser.parse_substitution(e.get_attr('name'))):
                    parser.parse_substitution(e.get_attr('value')) for e in env}
                for e in env:
                    e.assert_entity_completely_parsed()
        return cls, kwargs

    @property
    def name(self) -> Any:
        description = self.process_description
        return description.final_name if description.final_name is not None else description.name

    @property
    def cmd(self) -> Any:
        description = self.process_description
        return description.final_cmd if description.final_cmd is not None else description.cmd

    @property
    def cwd(self) -> Any:
        description = self.process_description
        return description.final_cwd if description.final_cwd is not None else description.cwd

    @property
    def env(self) -> Any:
        description = self.process_description
        return description.final_env if description.final_env is not None else description.env

    @property
    def additional_env(self) -> Any:
        return self.process_description.additional_env
