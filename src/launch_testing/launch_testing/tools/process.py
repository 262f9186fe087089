"""launch_process / ProcessProxy: start a process from a running test and watch it.

    with launch_testing.tools.launch_process(launch_service, ExecuteProcess(cmd=[...]),
                                             proc_info, proc_output) as command:
        assert command.wait_for_shutdown(timeout=10)
    assert command.exit_code == 0 and 'expected' in command.output

As upstream, the process is started by emitting launch's IncludeLaunchDescription event from
the test's thread (LaunchService.emit_event is thread-safe) and stopped on leaving the block
(ShutdownProcess) if it still runs.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from typing import Any

import launch.actions
import launch.events
from launch.events.process import ProcessExited, ProcessStarted, ShutdownProcess

import launch
from launch_testing.io_handler import ActiveIoHandler
from launch_testing.proc_info_handler import ActiveProcInfoHandler


def _ensure_type(value: Any, kind: type, name: str) -> None:
    if not isinstance(value, kind):
        raise TypeError(f"Expected '{name}' to be a '{kind.__name__}' but got "
                        f"'{type(value).__name__}'")


class _Verdict:
    """A bool that shows, in a failed assert, the output it was decided on."""

    def __init__(self, result: bool, output: str | None) -> None:
        self._result = result
        self._output = output

    def __bool__(self) -> bool:
        return self._result

    def __repr__(self) -> str:
        return f'<BoolWithText({self._result}): {self._output!r}>'


class ProcessProxy:
    """The state and output of one ExecuteProcess, as proc_info / proc_output record them."""

    def __init__(self, process_action: Any, proc_info: Any, proc_output: Any, *,
                 output_filter: Callable[[str], str] | None = None) -> None:
        _ensure_type(process_action, launch.actions.ExecuteProcess, 'process_action')
        _ensure_type(proc_info, ActiveProcInfoHandler, 'proc_info')
        _ensure_type(proc_output, ActiveIoHandler, 'proc_output')
        if output_filter is not None and not callable(output_filter):
            raise TypeError(f"Expected 'output_filter' to be callable but got "
                            f"'{output_filter!r}'")
        self._process_action = process_action
        self._proc_info = proc_info
        self._proc_output = proc_output
        self._output_filter = output_filter

    @property
    def target_process_action(self) -> Any:
        return self._process_action

    def _state(self) -> Any:
        if self._process_action not in self._proc_info.processes():
            return None
        return self._proc_info[self._process_action]

    @property
    def running(self) -> bool:
        return isinstance(self._state(), ProcessStarted)

    @property
    def terminated(self) -> bool:
        return isinstance(self._state(), ProcessExited)

    @property
    def exit_code(self) -> int | None:
        return self._proc_info[self._process_action].returncode

    def _text(self, stdout: bool | None) -> str:
        try:
            events = self._proc_output[self._process_action]
        except KeyError:  # no output (nor start) recorded yet
            events = []
        text = ''.join(event.text.decode(errors='replace') for event in events
                       if stdout is None or event.from_stdout == stdout)
        return text if self._output_filter is None else self._output_filter(text)

    @property
    def output(self) -> str:
        return self._text(None)

    @property
    def stdout(self) -> str:
        return self._text(True)

    @property
    def stderr(self) -> str:
        return self._text(False)

    def wait_for_shutdown(self, timeout: float | None = None) -> bool:
        """True once the process exited; False if `timeout` seconds passed first."""
        with self._proc_info.proc_event:
            return self._proc_info.proc_event.wait_for(lambda: self.terminated, timeout=timeout)

    def wait_for_output(self, condition: Callable[[str], bool] | None = None,
                        timeout: float | None = None) -> _Verdict:
        """Wait, while the process runs, until `condition(output)` holds (any output, by
        default); the result is falsy after `timeout` seconds and shows the output seen."""
        if condition is None:
            def condition(_output: str) -> bool:
                return True
        if not callable(condition):
            raise TypeError(f"Expected 'condition' to be callable but got '{condition!r}'")
        seen: list[str | None] = [None]

        def satisfied() -> bool:
            seen[0] = self.output
            return self.running and condition(seen[0])

        with self._proc_output.io_event:
            result = self._proc_output.io_event.wait_for(satisfied, timeout=timeout)
        return _Verdict(result, seen[0])


@contextlib.contextmanager
def launch_process(launch_service: Any, process_action: Any, proc_info: Any, proc_output: Any,
                   **kwargs: Any) -> Iterator[ProcessProxy]:
    """Start `process_action` in the running launch; yield a ProcessProxy (kwargs go to it);
    stop the process on leaving if it is still running."""
    _ensure_type(process_action, launch.actions.ExecuteProcess, 'process_action')
    launch_service.emit_event(event=launch.events.IncludeLaunchDescription(
        launch_description=launch.LaunchDescription([process_action])))
    proxy = ProcessProxy(process_action, proc_info, proc_output, **kwargs)
    try:
        yield proxy
    finally:
        if not proxy.terminated:
            launch_service.emit_event(event=ShutdownProcess(
                process_matcher=launch.events.matches_action(process_action)))
