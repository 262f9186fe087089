"""Single key presses from a terminal, for the keyboard teleop nodes."""

from __future__ import annotations

import termios


class RawTerminal:
    """Non-canonical, no-echo stdin (VMIN=0, VTIME=1: a read returns within 0.1 s, so a key
    loop can notice a stop request); the old settings come back on exit. With `signals`
    False, Ctrl-C arrives as the byte 0x03 instead of raising SIGINT (as a raw terminal)."""

    def __init__(self, fd: int, signals: bool = True) -> None:
        self.fd = fd
        self.signals = signals
        self.saved: list | None = None

    def __enter__(self) -> RawTerminal:
        self.saved = termios.tcgetattr(self.fd)
        raw = termios.tcgetattr(self.fd)
        raw[3] &= ~(termios.ICANON | termios.ECHO | (0 if self.signals else termios.ISIG))
        raw[6][termios.VMIN] = 0
        raw[6][termios.VTIME] = 1
        termios.tcsetattr(self.fd, termios.TCSANOW, raw)
        return self

    def __exit__(self, *exc: object) -> None:
        if self.saved is not None:
            termios.tcsetattr(self.fd, termios.TCSANOW, self.saved)
