"""LaunchService: runs launch descriptions on an asyncio loop until everything has stopped.

Entities are visited depth first as upstream does; events are handled one at a time; the
launch ends when nothing is pending (no process, timer or event) or after a shutdown, once
every process has exited. Then any process group of ours that still has members (a
grandchild that ignored SIGINT) gets SIGTERM, then SIGKILL, and orphans that were handed to
us (launch is a child subreaper) are stopped and reaped: nothing is left behind.
"""

from __future__ import annotations

import asyncio
import ctypes
import logging
import os
import signal
import time
from typing import Any

from launch import logging as launch_logging
from launch.actions.execute_process import signal_group
from launch.event import Event
from launch.event_handler import EventHandler
from launch.events import Shutdown
from launch.launch_context import LaunchContext
from launch.launch_description import LaunchDescription
from launch.launch_description_entity import LaunchDescriptionEntity

_PR_SET_CHILD_SUBREAPER = 36
_LEFTOVER_GRACE = 1.0  # seconds a process group member gets after its leader exited


class LaunchService:
    def __init__(self, *, argv: list[str] | None = None, noninteractive: bool = False,
                 debug: bool = False) -> None:
        self.__context = LaunchContext(argv=argv, noninteractive=noninteractive)
        self.__entities: list[LaunchDescriptionEntity] = []
        self.__return_code = 0
        self.__shutting_down = False
        self.__sigint_received = False
        if debug:
            launch_logging.set_level(logging.DEBUG)
        launch_logging.start_log_file()
        self.__logger = launch_logging.get_logger('launch')
        self.__logger.info(f'All log files can be found below {launch_logging.log_dir()}')
        self.__logger.info(f'Default logging verbosity is set to {launch_logging.level_name()}')

    @property
    def context(self) -> LaunchContext:
        return self.__context

    def include_launch_description(self, launch_description: LaunchDescription) -> None:
        self.__entities.append(launch_description)

    def emit_event(self, event: Event) -> None:
        self.__context.emit_event_sync(event)

    def shutdown(self, reason: str = 'LaunchService.shutdown() called') -> None:
        self._shutdown(reason, due_to_sigint=False)

    def run(self, *, shutdown_when_idle: bool = True) -> int:
        """Run until done; the return code is 1 when the launch itself failed, else 0."""
        return asyncio.run(self.run_async(shutdown_when_idle=shutdown_when_idle))

    async def run_async(self, *, shutdown_when_idle: bool = True) -> int:
        context = self.__context
        loop = asyncio.get_running_loop()
        context._loop = loop
        context._event_queue = asyncio.Queue()
        context.register_event_handler(EventHandler(
            matcher=lambda event: isinstance(event, Shutdown), entities=None), append=True)
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGQUIT):
            loop.add_signal_handler(sig, self._on_signal, sig)
        try:
            ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_CHILD_SUBREAPER, 1)
        except (OSError, AttributeError):
            pass
        pending: set[asyncio.Future] = set()
        try:
            self._visit(list(self.__entities), pending)
            while True:
                while not context._event_queue.empty():
                    self._handle(context._event_queue.get_nowait(), pending)
                pending = {future for future in pending if not future.done()}
                if not pending and context._event_queue.empty():
                    if context.is_shutdown or not shutdown_when_idle:
                        if context.is_shutdown:
                            break
                    else:
                        self._shutdown('idle', due_to_sigint=False)
                        continue
                getter = asyncio.ensure_future(context._event_queue.get())
                await asyncio.wait({getter, *pending}, return_when=asyncio.FIRST_COMPLETED)
                if getter.done():
                    self._handle(getter.result(), pending)
                else:
                    getter.cancel()
            await self._stop_leftovers()
        finally:
            for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGQUIT):
                loop.remove_signal_handler(sig)
        return self.__return_code

    # -- internals ------------------------------------------------------------------------
    def _on_signal(self, sig: int) -> None:
        if sig == signal.SIGINT:
            message = 'user interrupted with ctrl-c (SIGINT)'
            if self.__sigint_received:
                self.__logger.warning(f'{message} again, ignoring...')
                return
            self.__sigint_received = True
            self.__logger.warning(message)
            self._shutdown('ctrl-c (SIGINT)', due_to_sigint=True)
            return
        name = signal.Signals(sig).name
        # Upstream Jazzy abandons its processes here; we stop them as on Ctrl-C.
        self.__logger.warning(f'{name} received, stopping every process')
        self._shutdown(name, due_to_sigint=False)

    def _shutdown(self, reason: str, due_to_sigint: bool) -> None:
        if self.__shutting_down:
            return
        self.__shutting_down = True
        self.__context._is_shutdown = True
        self.__context.emit_event_sync(Shutdown(reason=reason, due_to_sigint=due_to_sigint))

    def _fail(self, error: BaseException) -> None:
        self.__logger.debug('exception in launch', exc_info=error)
        self.__logger.error(f'Caught exception in launch (see debug for traceback): {error}')
        self.__return_code = 1
        self._shutdown(f'Caught exception in launch: {error}', due_to_sigint=False)

    def _handle(self, event: Event, pending: set[asyncio.Future]) -> None:
        context = self.__context
        for handler in context.event_handlers:
            if not handler.matches(event):
                continue
            context._push_locals()
            try:
                entities = handler.handle(event, context)
                if entities is not None:
                    if not isinstance(entities, (list, tuple)):
                        entities = [entities]
                    self._visit(list(entities), pending)
            except Exception as error:
                self._fail(error)
            finally:
                context._pop_locals()

    def _visit(self, entities: list[Any], pending: set[asyncio.Future]) -> None:
        try:
            for entity in entities:
                if not isinstance(entity, LaunchDescriptionEntity):
                    raise TypeError(f'expected a launch action, got {type(entity).__name__}: '
                                    f'{entity!r}')
                sub_entities = entity.visit(self.__context)
                future = entity.get_asyncio_future()
                if future is not None:
                    pending.add(future)
                if sub_entities:
                    self._visit(list(sub_entities), pending)
        except Exception as error:
            self._fail(error)

    async def _stop_leftovers(self) -> None:
        """SIGTERM, then SIGKILL, whatever our processes left behind; reap adopted orphans."""
        groups = dict(self.__context._process_groups)
        deadline = time.monotonic() + _LEFTOVER_GRACE
        while time.monotonic() < deadline and any(_group_alive(g) for g in groups):
            _reap_orphans(self.__context._process_pids)
            await asyncio.sleep(0.05)
        for sig in (signal.SIGTERM, signal.SIGKILL):
            alive = [g for g in groups if _group_alive(g)]
            orphans = _orphans(self.__context._process_pids)
            if not alive and not orphans:
                return
            for pgid in alive:
                self.__logger.warning(f'processes left behind by [{groups[pgid]}] are still '
                                      f'running: sending {sig.name} to process group {pgid}')
                signal_group(pgid, sig)
            for pid in orphans:
                self.__logger.warning(f'process {pid}, left behind by a launched process, is '
                                      f'still running: sending {sig.name}')
                try:
                    os.kill(pid, sig)
                except ProcessLookupError:
                    pass
            deadline = time.monotonic() + 2.0
            while time.monotonic() < deadline:
                _reap_orphans(self.__context._process_pids)
                if not any(_group_alive(g) for g in groups) and not _orphans(
                        self.__context._process_pids):
                    return
                await asyncio.sleep(0.05)


def _group_alive(pgid: int) -> bool:
    return signal_group(pgid, 0)


def _orphans(known: set[int]) -> list[int]:
    """Our children that we did not start: grandchildren handed to us as their subreaper."""
    found: list[int] = []
    try:
        tasks = os.listdir('/proc/self/task')
    except OSError:
        return found
    for task in tasks:
        try:
            with open(f'/proc/self/task/{task}/children', encoding='ascii') as children:
                found.extend(int(pid) for pid in children.read().split())
        except OSError:
            continue
    return [pid for pid in found if pid not in known]


def _reap_orphans(known: set[int]) -> None:
    for pid in _orphans(known):
        try:
            os.waitpid(pid, os.WNOHANG)
        except ChildProcessError:
            pass
