"""IoHandler / ActiveIoHandler: what the launched processes wrote, and waiting for it."""

from __future__ import annotations

import threading
from collections.abc import Iterator
from typing import Any

from launch_testing.asserts.assert_output import assertInStream, stream_text
from launch_testing.util import NoMatchingProcessException, resolveProcesses

__unittest = True  # failures point at the test's line, not at this module (unittest's rule)

_TAIL_LINES = 5  # lines of a process's output a timed-out assertWaitFor shows


class IoHandler:
    """The ProcessIO events of every process, in order, and per process name."""

    def __init__(self) -> None:
        self._sequence: list[Any] = []
        self._by_name: dict[str, list[Any]] = {}
        self._actions: dict[str, Any] = {}

    def track(self, process_name: str, action: Any = None) -> None:
        self._by_name.setdefault(process_name, [])
        if action is not None:
            self._actions.setdefault(process_name, action)

    def append(self, process_io: Any) -> None:
        self._sequence.append(process_io)
        self.track(process_io.process_name, process_io.action)
        self._by_name[process_io.process_name].append(process_io)

    def __iter__(self) -> Iterator[Any]:
        return iter(list(self._sequence))

    def processes(self) -> list[Any]:
        """The ExecuteProcess actions of the processes seen (started or with output)."""
        return list(self._actions.values())

    def process_names(self) -> list[str]:
        return list(self._by_name)

    def __getitem__(self, key: Any) -> list[Any]:
        """The output events of a process, by name or by its ExecuteProcess action."""
        name = key if isinstance(key, str) else key.process_details['name']
        return list(self._by_name[name])


class ActiveIoHandler:
    """IoHandler filled by the launch while the tests run: lets them wait for output."""

    def __init__(self) -> None:
        self._sync_lock = threading.Condition()
        self._io_handler = IoHandler()

    @property
    def io_event(self) -> threading.Condition:
        return self._sync_lock

    def track(self, process_name: str, action: Any = None) -> None:
        with self._sync_lock:
            self._io_handler.track(process_name, action)
            self._sync_lock.notify_all()

    def append(self, process_io: Any) -> None:
        with self._sync_lock:
            self._io_handler.append(process_io)
            self._sync_lock.notify_all()

    def __iter__(self) -> Iterator[Any]:
        with self._sync_lock:
            return iter(self._io_handler)

    def processes(self) -> list[Any]:
        with self._sync_lock:
            return self._io_handler.processes()

    def process_names(self) -> list[str]:
        with self._sync_lock:
            return self._io_handler.process_names()

    def __getitem__(self, key: Any) -> list[Any]:
        with self._sync_lock:
            return self._io_handler[key]

    def assertWaitFor(self, expected_output: Any, process: Any = None,
                      cmd_args: Any = None, *, strict_proc_matching: bool = True,
                      output_filter: Any = None, timeout: float = 10,
                      strip_ansi_escape_sequences: bool = True, stream: str = 'stderr') -> None:
        """Wait up to `timeout` s for the output; fail saying what was awaited and seen."""
        found = self.waitFor(expected_output, process, cmd_args,
                             strict_proc_matching=strict_proc_matching,
                             output_filter=output_filter, timeout=timeout,
                             strip_ansi_escape_sequences=strip_ansi_escape_sequences,
                             stream=stream)
        assert found, self._timed_out_message(expected_output, process, cmd_args, timeout,
                                              stream)

    def waitFor(self, expected_output: Any, process: Any = None,
                cmd_args: Any = None, *, strict_proc_matching: bool = True,
                output_filter: Any = None, timeout: float = 10,
                strip_ansi_escape_sequences: bool = True, stream: str = 'stderr') -> bool:
        """True once the output is seen, False after `timeout` seconds."""
        if stream not in ('stdout', 'stderr'):
            raise ValueError(f"stream must be 'stdout' or 'stderr', got '{stream}'")

        def seen() -> bool:
            try:
                assertInStream(self._io_handler, expected_output, process, cmd_args,
                               output_filter=output_filter,
                               strict_proc_matching=strict_proc_matching,
                               strip_ansi_escape_sequences=strip_ansi_escape_sequences,
                               stream=stream)
                return True
            except (NoMatchingProcessException, AssertionError):
                return False  # no such process yet, or not printed yet: keep waiting

        with self._sync_lock:
            found = self._sync_lock.wait_for(seen, timeout=timeout)
        if not found and process is not None:
            try:
                resolveProcesses(self, process=process, cmd_args=cmd_args,
                                 strict_proc_matching=False)
            except NoMatchingProcessException:
                raise Exception(
                    f"After timeout, found no processes matching '{process}'  It either "
                    "doesn't exist, was never launched, or didn't generate any output") from None
        return found

    def _timed_out_message(self, expected: Any, process: Any, cmd_args: Any, timeout: float,
                           stream: str) -> str:
        """Upstream's 'Waiting for output timed out', then what was awaited and seen."""
        lines = ['Waiting for output timed out',
                 f"  expected {expected!r} on {stream} of "
                 f"{'any process' if process is None else repr(process)} within {timeout} s"]
        with self._sync_lock:
            try:
                candidates = resolveProcesses(self._io_handler, process=process,
                                              cmd_args=cmd_args, strict_proc_matching=False)
            except NoMatchingProcessException:
                candidates = []
            for action in candidates:
                name = action.process_details['name']
                text = stream_text(self._io_handler, action, stream).rstrip('\n')
                tail = text.split('\n')[-_TAIL_LINES:] if text else []
                lines.append(f'  last {stream} of {name}:' if tail else
                             f'  {name} wrote nothing to {stream}')
                lines.extend(f'    {line}' for line in tail)
        return '\n'.join(lines)
