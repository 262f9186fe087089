"""AsyncSafeSignalManager: signals handled on an asyncio loop, safely, while in its context.

It reads the signal numbers Python writes to its wakeup fd (signal.set_wakeup_fd) from a
socket pair on the loop, so a handler runs as an ordinary loop callback and may touch the
loop. Bytes are passed on to the wakeup fd that was set before, so asyncio's own signal
handling keeps working. While in context, a handled signal whose Python handler would end
the process (SIG_DFL, or SIGINT's KeyboardInterrupt) gets a no-op handler, restored on exit.
"""

from __future__ import annotations

import asyncio
import os
import signal
import socket
from collections.abc import Callable
from typing import Any

SignalHandler = Callable[[int], None]


def _ignore(signum: int, frame: Any) -> None:
    """Python-level handler that only lets the wakeup fd see the signal."""


class AsyncSafeSignalManager:
    def __init__(self, loop: asyncio.AbstractEventLoop) -> None:
        self.__loop = loop
        self.__handlers: dict[int, SignalHandler] = {}
        self.__reader: socket.socket | None = None
        self.__writer: socket.socket | None = None
        self.__previous_fd = -1
        self.__replaced: dict[int, Any] = {}

    def __enter__(self) -> AsyncSafeSignalManager:
        self.__reader, self.__writer = socket.socketpair()
        self.__reader.setblocking(False)
        self.__writer.setblocking(False)
        self.__loop.add_reader(self.__reader.fileno(), self.__dispatch)
        self.__previous_fd = signal.set_wakeup_fd(self.__writer.fileno())
        for signum in self.__handlers:
            self.__make_catchable(signum)
        return self

    def __exit__(self, *exc_info: Any) -> None:
        signal.set_wakeup_fd(self.__previous_fd)
        self.__previous_fd = -1
        for signum, previous in self.__replaced.items():
            signal.signal(signum, previous)
        self.__replaced.clear()
        if self.__reader is not None:
            self.__loop.remove_reader(self.__reader.fileno())
            self.__reader.close()
        if self.__writer is not None:
            self.__writer.close()
        self.__reader = self.__writer = None

    def __make_catchable(self, signum: int) -> None:
        current = signal.getsignal(signum)
        if signum not in self.__replaced and current in (
                signal.SIG_DFL, signal.default_int_handler):
            self.__replaced[signum] = signal.signal(signum, _ignore)

    def __dispatch(self) -> None:
        while self.__reader is not None:
            try:
                data = self.__reader.recv(4096)
            except InterruptedError:
                continue
            except BlockingIOError:
                return
            if not data:
                return
            for signum in data:
                handler = self.__handlers.get(signum)
                if handler is not None:
                    handler(signum)
            if self.__previous_fd != -1:
                try:
                    os.write(self.__previous_fd, data)
                except OSError:
                    pass

    def handle(self, signum: int, handler: SignalHandler | None) -> SignalHandler | None:
        """Register (or, with None, drop) the callback for a signal; returns the old one."""
        signum = signal.Signals(signum)
        if handler is None:
            return self.__handlers.pop(signum, None)
        if not callable(handler):
            raise ValueError('signal handler must be a callable')
        previous = self.__handlers.get(signum)
        self.__handlers[signum] = handler
        if self.__reader is not None:
            self.__make_catchable(signum)
        return previous
