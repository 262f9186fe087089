"""ExecuteLocal: runs a process (an Executable), its output prefixed with its name.

Each child runs in a session (and process group) of its own, so the signals launch sends
reach its own children too, and the terminal's Ctrl-C reaches only launch, which then stops
every child itself: SIGINT, SIGTERM after `sigterm_timeout` seconds, SIGKILL after
`sigkill_timeout` more. Should launch itself be killed outright, the kernel sends the child
SIGTERM (PR_SET_PDEATHSIG).
"""

from __future__ import annotations

import asyncio
import ctypes
import io
import logging
import os
import pty
import signal
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.conditions.evaluate_condition_expression_impl import evaluate_condition_expression
from launch.event_handler import BaseEventHandler
from launch.event_handlers.on_process_exit import OnProcessExit
from launch.event_handlers.on_shutdown import OnShutdown
from launch.events.process import (
    ProcessExited,
    ProcessStarted,
    ProcessStderr,
    ProcessStdout,
    ShutdownProcess,
    SignalProcess,
)
from launch.logging import get_logger, get_output_loggers
from launch.substitutions.launch_configuration import LaunchConfiguration
from launch.utilities import (
    is_a_subclass,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from launch.utilities.type_utils import normalize_typed_substitution, perform_typed_substitution

if TYPE_CHECKING:
    from launch.descriptions.executable import Executable
    from launch.events.process.process_exited import ProcessExited
    from launch.launch_context import LaunchContext
    from launch.launch_description_entity import LaunchDescriptionEntity
    from launch.some_entities_type import SomeEntitiesType
    from launch.some_substitutions_type import SomeSubstitutionsType

_PR_SET_PDEATHSIG = 1
# Default escalation delays: the launch arguments of these names, else 5 s (upstream).
_SIGTERM_TIMEOUT = LaunchConfiguration('sigterm_timeout', default=5)
_SIGKILL_TIMEOUT = LaunchConfiguration('sigkill_timeout', default=5)


def _die_with_parent(parent: int) -> Callable[[], None]:
    """A preexec_fn: the child gets SIGTERM when launch (pid `parent`) dies."""
    def in_child() -> None:  # runs in the child between fork and exec
        ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGTERM)
        if os.getppid() != parent:  # launch died before that took effect: run nothing
            os._exit(1)
    return in_child


def signal_group(pgid: int, sig: int) -> bool:
    """Signal a process group; False when nothing is left in it."""
    try:
        os.killpg(pgid, sig)
        return True
    except (ProcessLookupError, PermissionError):
        return False


class ExecuteLocal(Action):
    def __init__(
        self, *,
        process_description: Executable,
        shell: bool = False,
        sigterm_timeout: SomeSubstitutionsType = _SIGTERM_TIMEOUT,
        sigkill_timeout: SomeSubstitutionsType = _SIGKILL_TIMEOUT,
        emulate_tty: bool = False,
        output: SomeSubstitutionsType = 'log',
        output_format: str = '[{this.process_description.final_name}] {line}',
        cached_output: bool = False,
        log_cmd: bool = False,
        on_exit: SomeEntitiesType | Callable[[ProcessExited, LaunchContext],
                                            SomeEntitiesType | None] | None = None,
        respawn: bool | SomeSubstitutionsType = False,
        respawn_delay: float | None = None,
        respawn_max_retries: int = -1,
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        self.__process_description = process_description
        self.__shell = shell
        self.__sigterm_timeout = normalize_to_list_of_substitutions(sigterm_timeout)
        self.__sigkill_timeout = normalize_to_list_of_substitutions(sigkill_timeout)
        self.__emulate_tty = emulate_tty
        self.__output = output if isinstance(output, dict) else \
            normalize_to_list_of_substitutions(output)
        self.__output_format = output_format
        self.__cached_output = cached_output
        self.__log_cmd = log_cmd
        self.__on_exit = on_exit
        self.__respawn = normalize_typed_substitution(respawn, bool)
        self.__respawn_delay = respawn_delay
        self.__respawn_max_retries = respawn_max_retries
        self.__respawn_retries = 0
        self.__executed = False
        self.__process_event_args: dict[str, Any] | None = None
        self.__completed_future: asyncio.Future | None = None
        self.__shutdown_future: asyncio.Future | None = None
        self.__stdout_buffer = io.StringIO()
        self.__stderr_buffer = io.StringIO()
        self._process: asyncio.subprocess.Process | None = None
        self._exited: asyncio.Event | None = None
        self._stopping = False

    @property
    def process_description(self) -> Executable:
        return self.__process_description

    @property
    def shell(self) -> bool:
        return self.__shell

    @property
    def emulate_tty(self) -> bool:
        return self.__emulate_tty

    @property
    def sigterm_timeout(self) -> Any:
        return self.__sigterm_timeout

    @property
    def sigkill_timeout(self) -> Any:
        return self.__sigkill_timeout

    @property
    def output(self) -> Any:
        return self.__output

    @property
    def process_details(self) -> dict[str, Any] | None:
        return self.__process_event_args

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return self.__on_exit if isinstance(self.__on_exit, list) else []

    def get_asyncio_future(self) -> asyncio.Future | None:
        return self.__completed_future

    def get_stdout(self) -> str:
        """What the process wrote on stdout (needs cached_output=True)."""
        if not self.__cached_output:
            raise RuntimeError('cached output must be true to be able to get stdout, proc '
                               f"'{self.__process_description.name}'")
        return self.__stdout_buffer.getvalue()

    def get_stderr(self) -> str:
        """What the process wrote on stderr (needs cached_output=True)."""
        if not self.__cached_output:
            raise RuntimeError('cached output must be true to be able to get stderr, proc '
                               f"'{self.__process_description.name}'")
        return self.__stderr_buffer.getvalue()

    @property
    def return_code(self) -> int | None:
        return None if self._process is None else self._process.returncode

    # -- preparing ------------------------------------------------------------------------
    def prepare(self, context: LaunchContext) -> None:
        """Perform the substitutions: the final command, name, environment and options."""
        description = self.__process_description
        description.prepare(context, self)
        cmd = list(description.final_cmd or [])
        if self.__shell:
            cmd = [' '.join(cmd)]
        self.__process_event_args = {'action': self, 'name': description.final_name,
                                     'cmd': cmd, 'cwd': description.final_cwd,
                                     'env': description.final_env}
        self._respawn = perform_typed_substitution(context, self.__respawn, bool)
        self._sigterm_text = perform_substitutions(context, self.__sigterm_timeout)
        self._sigkill_text = perform_substitutions(context, self.__sigkill_timeout)
        self._sigterm_after = _seconds(self._sigterm_text, 'sigterm_timeout')
        self._sigkill_after = _seconds(self._sigkill_text, 'sigkill_timeout')
        self._tty = self.__emulate_tty
        if 'emulate_tty' in context.launch_configurations:
            self._tty = evaluate_condition_expression(context, normalize_to_list_of_substitutions(
                context.launch_configurations['emulate_tty']))
        output = self.__output
        override = os.environ.get('OVERRIDE_LAUNCH_PROCESS_OUTPUT')
        if override:
            output = override
        elif not isinstance(output, dict):
            output = perform_substitutions(context, output)
        self._stdout_logger, self._stderr_logger = get_output_loggers(
            description.final_name, output)

    # -- running --------------------------------------------------------------------------
    def execute(self, context: LaunchContext) -> None:
        self.prepare(context)
        details = self.__process_event_args
        assert details is not None
        if self.__executed:
            raise RuntimeError(f"ExecuteLocal action '{details['name']}': executed more than "
                               f'once: {self.describe()}')
        self.__executed = True
        if context.is_shutdown:
            return None
        self._logger = get_logger(details['name'])
        handlers: list[BaseEventHandler] = [
            _Callback(lambda event: is_a_subclass(event, ShutdownProcess)
                      and event.process_matcher(self), lambda event, ctx: self._stop(ctx)),
            _Callback(lambda event: is_a_subclass(event, SignalProcess)
                      and event.process_matcher(self), self._on_signal_process),
            OnShutdown(on_shutdown=lambda event, ctx: self._stop(ctx)),
        ]
        if self.__on_exit is not None:
            handlers.append(OnProcessExit(target_action=self, on_exit=self.__on_exit))
        for handler in handlers:
            context.register_event_handler(handler)
        loop = context.asyncio_loop
        assert loop is not None
        self.__completed_future = loop.create_future()
        self.__shutdown_future = loop.create_future()
        loop.create_task(self._run(context))
        return None

    async def _run(self, context: LaunchContext) -> None:
        try:
            while True:
                code = await self._run_once(context)
                if code is None or not self._should_respawn(context):
                    break
                self.__respawn_retries += 1
                if self.__respawn_delay:
                    await asyncio.wait([self.__shutdown_future], timeout=self.__respawn_delay)
                if self._stopping or context.is_shutdown:
                    break
        except Exception as error:  # a launch bug must not leave the launch waiting forever
            self._logger.error(f'{type(error).__name__}: {error}')
        finally:
            if not self.__completed_future.done():
                self.__completed_future.set_result(None)

    def _should_respawn(self, context: LaunchContext) -> bool:
        retries_left = (self.__respawn_max_retries < 0
                        or self.__respawn_retries < self.__respawn_max_retries)
        return self._respawn and not self._stopping and not context.is_shutdown and retries_left

    async def _run_once(self, context: LaunchContext) -> int | None:
        details = self.__process_event_args
        assert details is not None
        cmd = details['cmd']
        if self.__log_cmd:
            self._logger.info(f"process details: cmd='{' '.join(p for p in cmd if p.strip())}', "
                              f"cwd='{details['cwd']}', custom_env?=True")
        out_read, out_write = _stream(self._tty)
        err_read, err_write = _stream(self._tty)
        try:
            kwargs = dict(stdin=asyncio.subprocess.DEVNULL, stdout=out_write, stderr=err_write,
                          cwd=details['cwd'], env=details['env'], start_new_session=True,
                          preexec_fn=_die_with_parent(os.getpid()))
            if self.__shell:
                process = await asyncio.create_subprocess_shell(cmd[0], **kwargs)
            else:
                process = await asyncio.create_subprocess_exec(*cmd, **kwargs)
        except OSError as error:
            for fd in (out_read, out_write, err_read, err_write):
                os.close(fd)
            self._logger.error(f"exception occurred while executing process: '{cmd[0]}': "
                               f'{error.strerror}')
            return None
        os.close(out_write)
        os.close(err_write)
        self._process = process
        self._exited = asyncio.Event()
        pid = process.pid
        details['pid'] = pid
        context._process_groups[pid] = details['name']
        context._process_pids.add(pid)
        self._logger.info(f'process started with pid [{pid}]')
        event_args = {key: details[key] for key in ('action', 'name', 'cmd', 'cwd', 'env')}
        event_args['pid'] = pid
        await context.emit_event(ProcessStarted(**event_args))
        readers = [
            asyncio.ensure_future(self._forward(context, out_read, ProcessStdout, event_args,
                                                self._stdout_logger, self.__stdout_buffer)),
            asyncio.ensure_future(self._forward(context, err_read, ProcessStderr, event_args,
                                                self._stderr_logger, self.__stderr_buffer)),
        ]
        if self._stopping:  # shutdown came while the process was starting
            self._signal(signal.SIGINT, quiet=True)
        code = await process.wait()
        self._exited.set()
        context._process_pids.discard(pid)
        # A grandchild may hold the pipe open: give the readers a moment, then stop reading.
        await asyncio.wait(readers, timeout=0.5)
        for reader in readers:
            reader.cancel()
        await asyncio.gather(*readers, return_exceptions=True)
        if code == 0:
            self._logger.info(f'process has finished cleanly [pid {pid}]')
        else:
            self._logger.error(f"process has died [pid {pid}, exit code {code}, "
                               f"cmd '{' '.join(part for part in cmd if part.strip())}'].")
        await context.emit_event(ProcessExited(returncode=code, **event_args))
        return code

    async def _forward(self, context: LaunchContext, fd: int, event_type: type,
                       event_args: dict[str, Any], logger: logging.Logger,
                       cache: io.StringIO) -> None:
        """Read a child's stream; each line goes out prefixed with the process name."""
        loop = asyncio.get_running_loop()
        reader = asyncio.StreamReader(limit=1 << 20)
        transport, _ = await loop.connect_read_pipe(
            lambda: asyncio.StreamReaderProtocol(reader), os.fdopen(fd, 'rb', 0))
        try:
            while True:
                try:
                    raw = await reader.readline()
                except (OSError, ValueError):
                    break
                if not raw:
                    break
                context.emit_event_sync(event_type(text=raw, **event_args))
                line = raw.decode(errors='replace')
                if self.__cached_output:
                    cache.write(line)
                logger.info(self.__output_format.format(line=line.rstrip('\n').rstrip('\r'),
                                                        this=self))
        finally:
            transport.close()

    # -- stopping -------------------------------------------------------------------------
    def _signal(self, sig: int, quiet: bool = False) -> None:
        if self._process is None:
            return
        if not quiet:
            self._logger.info(f"sending signal '{signal.Signals(sig).name}' to "
                              f"process[{self.__process_event_args['name']}]")
        signal_group(self._process.pid, sig)

    def _on_signal_process(self, event: SignalProcess, context: LaunchContext) -> None:
        if self._process is None or self._process.returncode is not None:
            return None
        number = event.signal
        if isinstance(number, str):
            try:
                number = signal.Signals[number]
            except KeyError:
                self._logger.warning(f"signal name '{number}' is not supported")
                return None
        self._signal(number)
        return None

    def _stop(self, context: LaunchContext) -> None:
        if self._stopping:
            return None
        self._stopping = True
        if self.__shutdown_future is not None and not self.__shutdown_future.done():
            self.__shutdown_future.set_result(None)
        if self._process is None or self._process.returncode is not None:
            return None
        # Upstream relies on the terminal's Ctrl-C reaching the child; ours run in their own
        # process groups, so launch forwards it (it says so only when not interactive).
        self._signal(signal.SIGINT, quiet=not context.noninteractive)
        context.asyncio_loop.create_task(self._escalate())
        return None

    async def _escalate(self) -> None:
        name = self.__process_event_args['name']
        # As upstream's timers: SIGKILL comes sigterm_timeout + sigkill_timeout after the
        # SIGINT, and its line names that sum ('10.0' by default).
        since_sigint = str(self._sigterm_after + self._sigkill_after)
        for after, text, previous, sig in (
                (self._sigterm_after, self._sigterm_text, 'SIGINT', signal.SIGTERM),
                (self._sigkill_after, since_sigint, 'SIGTERM', signal.SIGKILL)):
            try:
                await asyncio.wait_for(self._exited.wait(), timeout=after)
                return
            except asyncio.TimeoutError:
                pass
            self._logger.error(f"process[{name}] failed to terminate '{text}' seconds after "
                               f"receiving '{previous}', escalating to '{sig.name}'")
            self._signal(sig)


class _Callback(BaseEventHandler):
    """Calls function(event, context) for the matching events."""

    def __init__(self, matcher: Any, function: Any) -> None:
        super().__init__(matcher=matcher)
        self.__function = function

    def handle(self, event: Any, context: LaunchContext) -> Any:
        return self.__function(event, context)


def _seconds(text: str, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{what} must be a number of seconds, got '{text}'") from None
    if value < 0:
        raise ValueError(f"{what} must not be negative, got '{text}'")
    return value


def _stream(tty: bool) -> tuple[int, int]:
    """(read end, write end): a pipe, or a pseudo-terminal when emulating a tty."""
    if tty:
        master, slave = pty.openpty()
        return master, slave
    return os.pipe()
