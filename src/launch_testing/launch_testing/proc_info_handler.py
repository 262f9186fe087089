"""ProcInfoHandler / ActiveProcInfoHandler: start and exit events of the processes."""

from __future__ import annotations

import threading
from collections.abc import Iterator
from typing import Any

from launch.events.process import ProcessExited

from launch_testing.util import NoMatchingProcessException, resolveProcesses

__unittest = True  # failures point at the test's line, not at this module (unittest's rule)


class ProcInfoHandler:
    """The latest event (ProcessStarted, then ProcessExited) of each process."""

    def __init__(self) -> None:
        self._proc_info: dict[Any, Any] = {}

    def append(self, process_info: Any) -> None:
        self._proc_info[process_info.action] = process_info

    def __iter__(self) -> Iterator[Any]:
        return iter(list(self._proc_info.values()))

    def processes(self) -> list[Any]:
        return list(self._proc_info)

    def process_names(self) -> list[str]:
        return [action.process_details['name'] for action in self._proc_info]

    def __getitem__(self, key: Any) -> Any:
        """The event of a process, by its ExecuteProcess action or (part of) its name."""
        if not isinstance(key, str):
            return self._proc_info[key]
        for action, info in self._proc_info.items():
            if key in action.process_details['name']:
                return info
        raise KeyError(key)


class ActiveProcInfoHandler:
    """ProcInfoHandler filled while the tests run: lets them wait for a start or an exit."""

    def __init__(self) -> None:
        self._sync_lock = threading.Condition()
        self._proc_info_handler = ProcInfoHandler()

    @property
    def proc_event(self) -> threading.Condition:
        return self._sync_lock

    def append(self, process_info: Any) -> None:
        with self._sync_lock:
            self._proc_info_handler.append(process_info)
            self._sync_lock.notify_all()

    def __iter__(self) -> Iterator[Any]:
        with self._sync_lock:
            return iter(self._proc_info_handler)

    def processes(self) -> list[Any]:
        with self._sync_lock:
            return self._proc_info_handler.processes()

    def process_names(self) -> list[str]:
        with self._sync_lock:
            return self._proc_info_handler.process_names()

    def __getitem__(self, key: Any) -> Any:
        with self._sync_lock:
            return self._proc_info_handler[key]

    def _wait(self, process: Any, cmd_args: Any, timeout: float, exited: bool) -> bool:
        def done() -> bool:
            try:
                action = resolveProcesses(self._proc_info_handler, process=process,
                                          cmd_args=cmd_args, strict_proc_matching=True)[0]
            except NoMatchingProcessException:
                return False
            return not exited or isinstance(self._proc_info_handler[action], ProcessExited)

        with self._sync_lock:
            return self._sync_lock.wait_for(done, timeout=timeout)

    def assertWaitForShutdown(self, process: Any, cmd_args: Any = None, *,
                              timeout: float = 10) -> None:
        assert self._wait(process, cmd_args, timeout, exited=True), \
            f"Timed out waiting for process '{process}' to finish"

    def assertWaitForStartup(self, process: Any, cmd_args: Any = None, *,
                             timeout: float = 10) -> None:
        assert self._wait(process, cmd_args, timeout, exited=False), \
            f"Timed out waiting for process '{process}' to start"
