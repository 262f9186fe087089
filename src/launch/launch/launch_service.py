"""LaunchService: runs launch descriptions on an asyncio loop until everything has stopped.

Entities are visited depth first as upstream does; events are handled one at a time; the
launch ends when nothing is pending (no process, timer or event) or after a shutdown, once
every process has exited. Then any process group of ours that still has members (a
grandchild that ignored SIGINT) gets SIGTERM, then SIGKILL, and orphans that were handed to
us (launch is a child subreaper) are stopped and reaped: nothing is left behind. Events may
be emitted from any thread (LaunchService.emit_event).
"""

from __future__ import annotations

import asyncio
import collections.abc
import concurrent.futures
import contextlib
import ctypes
import logging
import os
import signal
import threading
import time
import traceback
from collections.abc import Coroutine, Iterable, Iterator

from launch import logging as launch_logging
from launch.actions.execute_local import signal_group
from launch.event import Event
from launch.event_handlers.on_include_launch_description import OnIncludeLaunchDescription
from launch.event_handlers.on_shutdown import OnShutdown
from launch.events.include_launch_description import IncludeLaunchDescription
from launch.events.shutdown import Shutdown
from launch.launch_context import LaunchContext
from launch.launch_description import LaunchDescription
from launch.launch_description_entity import LaunchDescriptionEntity
from launch.utilities import (
    AsyncSafeSignalManager,
    is_a_subclass,
    visit_all_entities_and_collect_futures,
)

_PR_SET_CHILD_SUBREAPER = 36
_LEFTOVER_GRACE = 1.0  # seconds a process group member gets after its leader exited


def get_loop() -> asyncio.AbstractEventLoop:
    """This thread's event loop, made (and set) when there is none or it was closed."""
    try:
        return asyncio.get_running_loop()
    except RuntimeError:
        pass
    try:
        with contextlib.suppress(DeprecationWarning):
            loop = asyncio.get_event_loop_policy().get_event_loop()
        if not loop.is_closed():
            return loop
    except RuntimeError:
        pass
    loop = asyncio.new_event_loop()
    asyncio.set_event_loop(loop)
    return loop


class LaunchService:
    def __init__(self, *, argv: Iterable[str] | None = None, noninteractive: bool = False,
                 debug: bool = False) -> None:
        launch_logging.set_level(logging.DEBUG if debug else logging.INFO)
        self.__debug = debug
        self.__argv = list(argv) if argv is not None else []
        self.__logger = launch_logging.get_logger('launch')
        self.__context = LaunchContext(argv=self.__argv, noninteractive=noninteractive)
        self.__context.register_event_handler(OnIncludeLaunchDescription())
        self.__context.register_event_handler(OnShutdown(on_shutdown=self.__on_shutdown))
        self._entity_future_pairs: list[tuple[LaunchDescriptionEntity, asyncio.Future]] = []
        self.__loop_lock = threading.RLock()
        self.__loop_from_run_thread: asyncio.AbstractEventLoop | None = None
        self.__this_task: asyncio.Task | None = None
        self.__shutting_down = False
        self.__return_code = 0

    @property
    def context(self) -> LaunchContext:
        return self.__context

    @property
    def event_loop(self) -> asyncio.AbstractEventLoop | None:
        """The loop of the running launch (None when it is not running)."""
        return self.__loop_from_run_thread

    @property
    def task(self) -> asyncio.Task | None:
        return self.__this_task

    def emit_event(self, event: Event) -> None:
        """Emit an event, from any thread: queued until the launch runs, when it does not yet."""
        with self.__loop_lock:
            loop = self.__loop_from_run_thread
            if loop is None or _running_in(loop):
                self.__context.emit_event_sync(event)
                return
            future = asyncio.run_coroutine_threadsafe(self.__context.emit_event(event), loop)
        # Wait for the loop to take it, but not forever: a launch that ends meanwhile never
        # will (its event was too late anyway).
        while True:
            try:
                future.result(timeout=0.1)
                return
            except concurrent.futures.TimeoutError:
                if self.__loop_from_run_thread is not loop:
                    future.cancel()
                    return

    def include_launch_description(self, launch_description: LaunchDescription) -> None:
        """Visit a launch description (thread-safe: through an IncludeLaunchDescription event)."""
        self.emit_event(IncludeLaunchDescription(launch_description))

    def shutdown(self, force_sync: bool = False) -> Coroutine | None:
        """Stop the running launch (a no-op when it is not running); thread-safe.

        From within the launch's loop it returns a coroutine to await, unless force_sync.
        """
        with self.__loop_lock:
            if self.__loop_from_run_thread is None:
                return None
        # Not under the lock: from another thread this waits for the loop, which may need
        # the lock to finish its run.
        return self._shutdown(reason='LaunchService.shutdown() called', due_to_sigint=False,
                              force_sync=bool(force_sync))

    def run(self, *, shutdown_when_idle: bool = True) -> int:
        """Run until done; the return code is 1 when the launch itself failed, else 0."""
        loop = get_loop()
        task = loop.create_task(self.run_async(shutdown_when_idle=shutdown_when_idle))
        while True:
            try:
                return loop.run_until_complete(task)
            except KeyboardInterrupt:
                continue

    async def run_async(self, *, shutdown_when_idle: bool = True) -> int:
        if threading.current_thread() is not threading.main_thread():
            raise RuntimeError('LaunchService can only be run in the main thread.')
        with self._prepare_run_loop() as (loop, _task):
            launch_logging.start_log_file()
            self.__logger.info(f'All log files can be found below {launch_logging.log_dir()}')
            self.__logger.info('Default logging verbosity is set to '
                               f'{launch_logging.level_name()}')
            try:
                ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_CHILD_SUBREAPER, 1)
            except (OSError, AttributeError):
                pass
            self.__return_code = 0

            def on_loop_exception(loop: asyncio.AbstractEventLoop, context: dict) -> None:
                self.__return_code = 1
                loop.default_exception_handler(context)
            loop.set_exception_handler(on_loop_exception)
            await self._main_loop(loop, shutdown_when_idle)
            await self._stop_leftovers()
            return self.__return_code

    async def _main_loop(self, loop: asyncio.AbstractEventLoop,
                         shutdown_when_idle: bool) -> None:
        event_task: asyncio.Task | None = None
        while True:
            try:
                idle = self._is_idle()
                if not self.__shutting_down and shutdown_when_idle and idle:
                    pending = self._shutdown(reason='idle', due_to_sigint=False)
                    if pending is not None:
                        await pending
                    continue
                if self.__shutting_down and idle:
                    if event_task is not None and not event_task.done():
                        event_task.cancel()
                    return
                waited: list[asyncio.Future] = []
                if self.__context._event_queue.empty():
                    waited = [future for _, future in self._entity_future_pairs]
                    waited.extend(self.__context._completion_futures)
                if event_task is None or event_task.done():
                    event_task = loop.create_task(self._process_one_event())
                waited.append(event_task)
                done, _ = await asyncio.wait(waited, return_when=asyncio.FIRST_COMPLETED)
                errors = [task.exception() for task in done
                          if not task.cancelled() and task.exception() is not None]
                for extra in errors[1:]:
                    self.__logger.error(extra)
                if errors:
                    raise errors[0]
            except KeyboardInterrupt:
                continue
            except asyncio.CancelledError:
                self.__logger.error('run task was canceled')
                self.__return_code = 1
                return
            except Exception as error:
                message = f'Caught exception in launch (see debug for traceback): {error}'
                self.__logger.debug(traceback.format_exc())
                self.__logger.error(message)
                self.__return_code = 1
                pending = self._shutdown(reason=message, due_to_sigint=False)
                if pending is not None:
                    await pending

    @contextlib.contextmanager
    def _prepare_run_loop(self) -> Iterator[tuple[asyncio.AbstractEventLoop, asyncio.Task]]:
        with self.__loop_lock:
            if self.__loop_from_run_thread is not None:
                raise RuntimeError('LaunchService cannot be run multiple times concurrently.')
            loop = asyncio.get_running_loop()
            if self.__debug:
                loop.set_debug(True)
            self.__context._set_asyncio_loop(loop)
            # Events emitted before the run (include_launch_description) move to a queue of
            # this loop.
            queue: asyncio.Queue = asyncio.Queue()
            while not self.__context._event_queue.empty():
                queue.put_nowait(self.__context._event_queue.get_nowait())
            self.__context._event_queue = queue
            self.__loop_from_run_thread = loop
        task = asyncio.current_task(loop)
        assert task is not None
        self.__this_task = task
        sigint_seen = False

        def on_sigint(signum: int) -> None:
            nonlocal sigint_seen
            message = 'user interrupted with ctrl-c (SIGINT)'
            if sigint_seen:
                self.__logger.warning(f'{message} again, ignoring...')
                return
            sigint_seen = True
            self.__logger.warning(message)
            self._shutdown(reason='ctrl-c (SIGINT)', due_to_sigint=True, force_sync=True)

        def on_sigterm(signum: int) -> None:
            # Upstream abandons its processes here; we stop them as on Ctrl-C.
            name = signal.Signals(signum).name
            self.__logger.warning(f'{name} received, stopping every process')
            self._shutdown(reason=name, due_to_sigint=False, force_sync=True)

        try:
            with AsyncSafeSignalManager(loop) as manager:
                manager.handle(signal.SIGINT, on_sigint)
                manager.handle(signal.SIGTERM, on_sigterm)
                manager.handle(signal.SIGQUIT, on_sigterm)
                yield loop, task
        finally:
            with self.__loop_lock:
                self.__context._set_asyncio_loop(None)
                self.__loop_from_run_thread = None
                self.__shutting_down = False

    def _prune(self) -> int:
        self._entity_future_pairs = [pair for pair in self._entity_future_pairs
                                     if not pair[1].done()]
        self.__context._completion_futures = [future for future in
                                              self.__context._completion_futures
                                              if not future.done()]
        return len(self._entity_future_pairs) + len(self.__context._completion_futures)

    def _is_idle(self) -> bool:
        return self._prune() == 0 and self.__context._event_queue.empty()

    async def _process_one_event(self) -> None:
        event = await self.__context._event_queue.get()
        await self.__process_event(event)

    async def __process_event(self, event: Event) -> None:
        self.__logger.debug(f"processing event: '{event}'")
        for handler in tuple(self.__context._event_handlers):
            if not handler.matches(event):
                continue
            self.__logger.debug(f"processing event: '{event}' ✓ '{handler}'")
            self.__context._push_locals()
            try:
                entities = handler.handle(event, self.__context)
                if not isinstance(entities, collections.abc.Iterable):
                    entities = (entities,)
                for entity in [e for e in entities if e is not None]:
                    if not is_a_subclass(entity, LaunchDescriptionEntity):
                        raise RuntimeError('expected a LaunchDescriptionEntity from '
                                           f"event_handler, got '{entity}'")
                    self._entity_future_pairs.extend(
                        visit_all_entities_and_collect_futures(entity, self.__context))
            finally:
                self.__context._pop_locals()

    def __on_shutdown(self, event: Event, context: LaunchContext) -> None:
        self.__shutting_down = True
        self.__context._set_is_shutdown(True)
        return None

    def _shutdown(self, *, reason: str, due_to_sigint: bool, force_sync: bool = False
                  ) -> Coroutine | None:
        """Emit Shutdown once; later calls (a timer, Ctrl-C after a shutdown) do nothing."""
        pending = None
        if not self.__shutting_down:
            event = Shutdown(reason=reason, due_to_sigint=due_to_sigint)
            loop = self.__loop_from_run_thread
            if force_sync or loop is None:
                self.__context.emit_event_sync(event)
            elif _running_in(loop):
                pending = self.__context.emit_event(event)
            else:
                self.emit_event(event)
        self.__shutting_down = True
        self.__context._set_is_shutdown(True)
        return pending

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


def _running_in(loop: asyncio.AbstractEventLoop) -> bool:
    try:
        return asyncio.get_running_loop() is loop
    except RuntimeError:
        return False


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
