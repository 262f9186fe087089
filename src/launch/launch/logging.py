"""launch's output: `[LEVEL] [name]: message` and `[process-N] line` on the screen.

Everything shown (and a child's stdout that `output='log'` keeps off the screen) also goes,
with a time stamp, to `launch.log` in this run's log directory, like upstream's.
"""

from __future__ import annotations

import datetime
import logging
import os
import socket
import sys
import time
from typing import TextIO

_loggers: dict[str, logging.Logger] = {}
_level = logging.INFO
_log_dir: str | None = None
_log_file: TextIO | None = None


def log_dir() -> str:
    """This run's log directory: ROS_LOG_DIR, else $ROS_HOME/log, else ~/.ros/log, + a stamp."""
    global _log_dir
    if _log_dir is None:
        base = os.environ.get('ROS_LOG_DIR') or os.path.join(
            os.environ.get('ROS_HOME') or os.path.join(os.path.expanduser('~'), '.ros'), 'log')
        stamp = datetime.datetime.now().strftime('%Y-%m-%d-%H-%M-%S-%f')
        _log_dir = os.path.join(base, f'{stamp}-{socket.gethostname()}-{os.getpid()}')
    return _log_dir


def _open_log_file() -> None:
    global _log_file
    if _log_file is None:
        try:
            os.makedirs(log_dir(), exist_ok=True)
            _log_file = open(os.path.join(log_dir(), 'launch.log'), 'a', encoding='utf-8')
        except OSError:
            _log_file = None  # an unwritable log directory must not stop the launch


def _write(text: str, screen: bool) -> None:
    if screen:
        try:
            sys.stdout.write(text + '\n')
            sys.stdout.flush()
        except (BrokenPipeError, ValueError):
            pass  # the reader went away: keep launching, as upstream does
    if _log_file is not None:
        _log_file.write(f'{time.time():.7f} {text}\n')
        _log_file.flush()


class _Handler(logging.Handler):
    def emit(self, record: logging.LogRecord) -> None:
        _write(f'[{record.levelname}] [{record.name}]: {record.getMessage()}', screen=True)


_handler = _Handler()


def get_logger(name: str = 'launch') -> logging.Logger:
    """A logger printing `[LEVEL] [name]: message` (upstream's screen format)."""
    logger = _loggers.get(name)
    if logger is None:
        logger = logging.Logger(name, _level)
        logger.addHandler(_handler)
        _loggers[name] = logger
    return logger


def set_level(level: int) -> None:
    global _level
    _level = level
    for logger in _loggers.values():
        logger.setLevel(level)


def level_name() -> str:
    return logging.getLevelName(_level)


def start_log_file() -> None:
    """Create the log directory and open launch.log (called once the service starts)."""
    _open_log_file()


def process_output(name: str, line: str, screen: bool) -> None:
    """One line a child wrote: `[name] line` on the screen when `screen`, always in the file."""
    _write(f'[{name}] {line}', screen=screen)


class _LaunchConfig:
    """Upstream's `launch.logging.launch_config`: the log directory and the level."""

    @property
    def log_dir(self) -> str:
        return log_dir()

    @log_dir.setter
    def log_dir(self, path: str) -> None:
        global _log_dir
        _log_dir = path

    @property
    def level(self) -> int:
        return _level

    @level.setter
    def level(self, new_level: int) -> None:
        set_level(new_level)


launch_config = _LaunchConfig()
