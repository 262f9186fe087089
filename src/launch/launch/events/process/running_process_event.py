"""RunningProcessEvent: the base of the events about one running process."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.event import Event

if TYPE_CHECKING:
    from launch.actions.execute_process import ExecuteProcess


class RunningProcessEvent(Event):
    name = 'launch.events.process.RunningProcessEvent'

    def __init__(self, *, action: ExecuteProcess, name: str, cmd: list[str], cwd: str | None,
                 env: dict[str, str] | None, pid: int) -> None:
        self.__action = action
        self.__name = name
        self.__cmd = cmd
        self.__cwd = cwd
        self.__env = env
        self.__pid = pid

    @property
    def action(self) -> Any:
        return self.__action

    @property
    def execute_process_action(self) -> Any:
        return self.__action

    @property
    def process_name(self) -> str:
        return self.__name

    @property
    def cmd(self) -> list[str]:
        return self.__cmd

    @property
    def cwd(self) -> str | None:
        return self.__cwd

    @property
    def env(self) -> dict[str, str] | None:
        return self.__env

    @property
    def pid(self) -> int:
        return self.__pid
