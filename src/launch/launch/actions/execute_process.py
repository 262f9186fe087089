"""ExecuteProcess: a child process, its output prefixed with its name, stopped cleanly.

Each child runs in a session (and process group) of its own, so the signals launch sends
reach its own children too, and the terminal's Ctrl-C reaches only launch, which then stops
every child itself: SIGINT, SIGTERM after `sigterm_timeout` seconds, SIGKILL after
`sigkill_timeout` more. Should launch itself be killed outright, the kernel sends the child
SIGTERM (PR_SET_PDEATHSIG).
"""

from __future__ import annotations

import asyncio
import ctypes
import os
import pty
import shlex
import signal
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.conditions import evaluate_condition_expression
from launch.event_handler import EventHandler
from launch.event_handlers import OnProcessExit
from launch.events import ExecutionComplete, Shutdown
from launch.events.process import (
    ProcessExited,
    ProcessStarted,
    ProcessStderr,
    ProcessStdout,
    ShutdownProcess,
    SignalProcess,
)
from launch.frontend.expose import expose_action
from launch.logging import get_logger, process_output
from launch.substitution import (
    SomeSubstitutionsType,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from launch.substitutions import LaunchConfiguration

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext

_PR_SET_PDEATHSIG = 1
_process_counter = 0  # upstream numbers processes across the whole launch: name-1, name-2...
_OUTPUTS = ('screen', 'log', 'both', 'own_log', 'full')


def _die_with_parent() -> None:
    # Runs in the child between fork and exec.
    ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGTERM)


def signal_group(pgid: int, sig: int) -> bool:
    """Signal a process group; False when nothing is left in it."""
    try:
        os.killpg(pgid, sig)
        return True
    except (ProcessLookupError, PermissionError):
        return False


class _ProcessDescription:
    """What the process became once substitutions were performed (upstream's naming)."""

    def __init__(self, name: str, cmd: list[str]) -> None:
        self.final_name = name
        self.final_cmd = cmd


@expose_action('executable')
class ExecuteProcess(Action):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        from launch.frontend.entity import FrontendError
        cmd = entity.get_words('cmd')
        if not cmd:
            raise FrontendError("<executable> needs the attribute 'cmd'")
        extra = entity.get_words('args') or []
        kwargs = {'cmd': cmd + extra, 'name': entity.get_substitutions('name'),
                  'shell': entity.get_bool('shell', False)}
        return cls, {**kwargs, **cls.parse_process_options(entity)}

    @classmethod
    def parse_process_options(cls, entity: Entity) -> dict[str, Any]:
        """What every process tag (executable, node) may set: condition, output, env, ..."""
        from launch.frontend.parse_substitution import parse_substitutions
        options: dict[str, Any] = dict(cls.parse_condition(entity))
        for attribute, key in (('output', 'output'), ('launch-prefix', 'prefix'),
                               ('launch_prefix', 'prefix'), ('cwd', 'cwd'),
                               ('sigterm_timeout', 'sigterm_timeout'),
                               ('sigkill_timeout', 'sigkill_timeout')):
            value = entity.get_substitutions(attribute)
            if value is not None:
                options[key] = value
        if entity.get('respawn') is not None:
            options['respawn'] = parse_substitutions(entity.get('respawn'))
        if entity.get('respawn_delay') is not None:
            options['respawn_delay'] = float(entity.get('respawn_delay'))
        if entity.get('emulate_tty') is not None:
            options['emulate_tty'] = entity.get_bool('emulate_tty', False)
        env = {}
        for child in entity.children_of('env'):
            env[tuple(child.get_substitutions('name', True))] = child.get_substitutions(
                'value', True)
            child.check_all_used()
        if env:
            options['additional_env'] = env
        return options

    def __init__(
        self, *,
        cmd: Iterable[SomeSubstitutionsType],
        name: SomeSubstitutionsType | None = None,
        cwd: SomeSubstitutionsType | None = None,
        env: dict | None = None,
        additional_env: dict | None = None,
        shell: bool = False,
        sigterm_timeout: SomeSubstitutionsType | None = None,
        sigkill_timeout: SomeSubstitutionsType | None = None,
        emulate_tty: bool = False,
        output: SomeSubstitutionsType | dict = 'log',
        output_format: str = '[{this.process_description.final_name}] {line}',
        cached_output: bool = False,
        log_cmd: bool = False,
        on_exit: Any = None,
        respawn: bool | SomeSubstitutionsType = False,
        respawn_delay: float | None = None,
        respawn_max_retries: int = -1,
        prefix: SomeSubstitutionsType | None = None,
        **kwargs: Any,
    ) -> None:
        super().__init__(**kwargs)
        if isinstance(cmd, (str, os.PathLike)):
            cmd = [cmd]
        self.cmd = [normalize_to_list_of_substitutions(part) for part in cmd]
        self.name = None if name is None else normalize_to_list_of_substitutions(name)
        self.cwd = None if cwd is None else normalize_to_list_of_substitutions(cwd)
        self.env = env
        self.additional_env = additional_env
        self.shell = shell
        # Default: the launch arguments sigterm_timeout / sigkill_timeout, else 5 s (upstream).
        self.sigterm_timeout = normalize_to_list_of_substitutions(
            LaunchConfiguration('sigterm_timeout', default='5') if sigterm_timeout is None
            else sigterm_timeout)
        self.sigkill_timeout = normalize_to_list_of_substitutions(
            LaunchConfiguration('sigkill_timeout', default='5') if sigkill_timeout is None
            else sigkill_timeout)
        self.emulate_tty = emulate_tty
        self.output = output if isinstance(output, dict) else \
            normalize_to_list_of_substitutions(output)
        self.log_cmd = log_cmd
        self.respawn = respawn
        self.respawn_delay = respawn_delay
        self.respawn_max_retries = respawn_max_retries
        self.prefix = None if prefix is None else normalize_to_list_of_substitutions(prefix)
        self.on_exit = on_exit
        self.process_details: dict[str, Any] = {}
        self.process_description: _ProcessDescription | None = None
        self._executed = False
        self._completed: asyncio.Future | None = None
        self._stopping = False
        self._stop_requested: asyncio.Event | None = None
        self._process: asyncio.subprocess.Process | None = None
        self._exited: asyncio.Event | None = None
        self._retries = 0

    def describe(self) -> str:
        return f'ExecuteProcess(cmd=[{", ".join(str(c) for c in self.cmd)}])'

    def get_asyncio_future(self) -> asyncio.Future | None:
        return self._completed

    # -- preparing ------------------------------------------------------------------------
    def _perform(self, context: LaunchContext, subs: Any) -> str:
        return perform_substitutions(context, normalize_to_list_of_substitutions(subs))

    def _prepare(self, context: LaunchContext) -> None:
        global _process_counter
        cmd = [perform_substitutions(context, part) for part in self.cmd]
        cmd = [part for part in cmd if part != ''] if not self.shell else cmd
        if not cmd:
            raise ValueError('ExecuteProcess: empty cmd')
        if self.prefix is not None:
            cmd = shlex.split(perform_substitutions(context, self.prefix)) + cmd
        if self.shell:
            cmd = [' '.join(cmd)]
        base = (perform_substitutions(context, self.name) if self.name is not None
                else os.path.basename(cmd[0]))
        _process_counter += 1
        name = f'{base}-{_process_counter}'
        env = dict(context.environment)
        if self.env is not None:
            env = {self._perform(context, k): self._perform(context, v)
                   for k, v in dict(self.env).items()}
        for key, value in dict(self.additional_env or {}).items():
            env[self._perform(context, key)] = self._perform(context, value)
        cwd = None if self.cwd is None else perform_substitutions(context, self.cwd)
        self.process_description = _ProcessDescription(name, cmd)
        self.process_details = {'name': name, 'cmd': cmd, 'cwd': cwd, 'env': env}
        self._respawn = self.respawn if isinstance(self.respawn, bool) else \
            evaluate_condition_expression(context, normalize_to_list_of_substitutions(
                self.respawn))
        self._sigterm_text = perform_substitutions(context, self.sigterm_timeout)
        self._sigkill_text = perform_substitutions(context, self.sigkill_timeout)
        self._sigterm_after = _seconds(self._sigterm_text, 'sigterm_timeout')
        self._sigkill_after = _seconds(self._sigkill_text, 'sigkill_timeout')
        self._tty = self.emulate_tty
        if 'emulate_tty' in context.launch_configurations:
            self._tty = evaluate_condition_expression(context, normalize_to_list_of_substitutions(
                context.launch_configurations['emulate_tty']))
        output = self.output
        override = os.environ.get('OVERRIDE_LAUNCH_PROCESS_OUTPUT')
        if override:
            output = override
        elif not isinstance(output, dict):
            output = perform_substitutions(context, output)
        self._screen_stdout, self._screen_stderr = _screen_streams(output)

    # -- running --------------------------------------------------------------------------
    def execute(self, context: LaunchContext) -> None:
        if self._executed:
            raise RuntimeError(f'ExecuteProcess executed more than once: {self.describe()}')
        self._executed = True
        if context.is_shutdown:
            return None
        self._prepare(context)
        self._logger = get_logger(self.process_details['name'])
        context.register_event_handler(_Callback(
            lambda event: isinstance(event, Shutdown), self._on_shutdown))
        context.register_event_handler(_Callback(
            lambda event: isinstance(event, SignalProcess) and event.process_matcher(self),
            self._on_signal_process))
        context.register_event_handler(_Callback(
            lambda event: isinstance(event, ShutdownProcess) and event.process_matcher(self),
            lambda event, ctx: self._stop(ctx)))
        if self.on_exit is not None:
            context.register_event_handler(OnProcessExit(target_action=self,
                                                         on_exit=self.on_exit))
        loop = context.asyncio_loop
        self._completed = loop.create_future()
        self._stop_requested = asyncio.Event()
        loop.create_task(self._run(context))
        return None

    async def _run(self, context: LaunchContext) -> None:
        try:
            while True:
                code = await self._run_once(context)
                if code is None or not self._should_respawn(context):
                    break
                self._retries += 1
                if self.respawn_delay:
                    try:
                        await asyncio.wait_for(self._stop_requested.wait(),
                                               timeout=float(self.respawn_delay))
                    except asyncio.TimeoutError:
                        pass
                if self._stopping or context.is_shutdown:
                    break
        except Exception as error:  # a launch bug must not leave the launch waiting forever
            self._logger.error(f'{type(error).__name__}: {error}')
        finally:
            if not self._completed.done():
                self._completed.set_result(None)
            context.emit_event_sync(ExecutionComplete(action=self))

    def _should_respawn(self, context: LaunchContext) -> bool:
        return (self._respawn and not self._stopping and not context.is_shutdown
                and (self.respawn_max_retries < 0 or self._retries < self.respawn_max_retries))

    async def _run_once(self, context: LaunchContext) -> int | None:
        details = self.process_details
        cmd = details['cmd']
        if self.log_cmd:
            self._logger.info(f"process details: cmd='{' '.join(cmd)}', cwd='{details['cwd']}', "
                              f"custom_env?={self.env is not None}")
        out_read, out_write = _stream(self._tty)
        err_read, err_write = _stream(self._tty)
        try:
            kwargs = dict(stdin=asyncio.subprocess.DEVNULL, stdout=out_write, stderr=err_write,
                          cwd=details['cwd'], env=details['env'], start_new_session=True,
                          preexec_fn=_die_with_parent)
            if self.shell:
                process = await asyncio.create_subprocess_shell(cmd[0], **kwargs)
            else:
                process = await asyncio.create_subprocess_exec(*cmd, **kwargs)
        except OSError as error:
            for fd in (out_read, out_write, err_read, err_write):
                os.close(fd)
            self._logger.error(f"failed to start '{cmd[0]}': {error.strerror}")
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
        event_args = dict(action=self, name=details['name'], cmd=cmd, cwd=details['cwd'],
                          env=details['env'], pid=pid)
        context.emit_event_sync(ProcessStarted(**event_args))
        readers = [
            asyncio.ensure_future(self._forward(context, out_read, ProcessStdout, event_args,
                                                self._screen_stdout)),
            asyncio.ensure_future(self._forward(context, err_read, ProcessStderr, event_args,
                                                self._screen_stderr)),
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
        context.emit_event_sync(ProcessExited(returncode=code, **event_args))
        return code

    async def _forward(self, context: LaunchContext, fd: int, event_type: type,
                       event_args: dict[str, Any], screen: bool) -> None:
        """Read a child's stream; each line goes out prefixed with the process name."""
        loop = asyncio.get_running_loop()
        reader = asyncio.StreamReader(limit=1 << 20)
        transport, _ = await loop.connect_read_pipe(
            lambda: asyncio.StreamReaderProtocol(reader), os.fdopen(fd, 'rb', 0))
        name = self.process_details['name']
        try:
            while True:
                try:
                    raw = await reader.readline()
                except (OSError, ValueError):
                    break
                if not raw:
                    break
                context.emit_event_sync(event_type(text=raw, **event_args))
                line = raw.decode(errors='replace').rstrip('\n').rstrip('\r')
                process_output(name, line, screen)
        finally:
            transport.close()

    # -- stopping -------------------------------------------------------------------------
    def _signal(self, sig: int, quiet: bool = False) -> None:
        if self._process is None:
            return
        if not quiet:
            self._logger.info(f"sending signal '{signal.Signals(sig).name}' to "
                              f"process[{self.process_details['name']}]")
        signal_group(self._process.pid, sig)

    def _on_signal_process(self, event: SignalProcess, context: LaunchContext) -> None:
        if self._process is not None and self._process.returncode is None:
            self._signal(event.signal)

    def _on_shutdown(self, event: Shutdown, context: LaunchContext) -> None:
        self._stop(context)

    def _stop(self, context: LaunchContext) -> None:
        if self._stopping:
            return
        self._stopping = True
        if self._stop_requested is not None:
            self._stop_requested.set()
        if self._process is None or self._process.returncode is not None:
            return
        # Upstream relies on the terminal's Ctrl-C reaching the child; ours run in their own
        # process groups, so launch forwards it (it says so only when not interactive).
        self._signal(signal.SIGINT, quiet=not context.noninteractive)
        context.asyncio_loop.create_task(self._escalate())

    async def _escalate(self) -> None:
        name = self.process_details['name']
        for after, text, previous, sig in (
                (self._sigterm_after, self._sigterm_text, 'SIGINT', signal.SIGTERM),
                (self._sigkill_after, self._sigkill_text, 'SIGTERM', signal.SIGKILL)):
            try:
                await asyncio.wait_for(self._exited.wait(), timeout=after)
                return
            except asyncio.TimeoutError:
                pass
            self._logger.error(f"process[{name}] failed to terminate '{text}' seconds after "
                               f"receiving '{previous}', escalating to '{sig.name}'")
            self._signal(sig)


class _Callback(EventHandler):
    """Internal handler calling a function of (event, context)."""

    def __init__(self, matcher: Any, function: Any) -> None:
        super().__init__(matcher=matcher)
        self.function = function

    def handle(self, event: Any, context: LaunchContext) -> Any:
        return self.function(event, context)


def _seconds(text: str, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{what} must be a number of seconds, got '{text}'") from None
    if value < 0:
        raise ValueError(f"{what} must not be negative, got '{text}'")
    return value


def _screen_streams(output: Any) -> tuple[bool, bool]:
    """(stdout on screen?, stderr on screen?) for an `output` setting, as upstream routes it."""
    if isinstance(output, dict):
        return (output.get('stdout', 'log') in ('screen', 'both'),
                output.get('stderr', 'log') in ('screen', 'both'))
    if output not in _OUTPUTS:
        raise ValueError(f"output must be one of {list(_OUTPUTS)}, got '{output}'")
    if output in ('screen', 'both'):
        return True, True
    if output == 'log':
        return False, True  # upstream: stdout to the log file, stderr to both
    return False, False


def _stream(tty: bool) -> tuple[int, int]:
    """(read end, write end): a pipe, or a pseudo-terminal when emulating a tty."""
    if tty:
        master, slave = pty.openpty()
        return master, slave
    return os.pipe()
