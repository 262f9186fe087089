"""launch.logging: launch's logs on the screen and in this run's log directory (upstream's API).

Loggers are Python loggers; the root logger gets a screen handler (`[LEVEL] [name]: message`)
and the `launch.log` file handler (`<time> [LEVEL] [name]: message`). A launched process's
output goes through its own pair of loggers (get_output_loggers), whose `output` setting
says where each stream goes: the screen, launch.log, and/or the process's own log files.
The log directory is `$ROS_LOG_DIR`, else `$ROS_HOME/log`, else `~/.ros/log`, plus a
directory of this run's own (`latest` points at it).
"""

from __future__ import annotations

import datetime
import logging
import os
import socket
import sys
from collections.abc import Callable
from typing import Any

from launch.logging import handlers

__all__ = ['get_logger', 'get_output_loggers', 'handlers', 'launch_config', 'log_dir',
           'log_launch_config', 'reset']

_SCREEN_DEFAULT = '[{levelname}] [{name}]: {msg}'
_SCREEN_WITH_TIMESTAMP = '{created:.7f} [{levelname}] [{name}]: {msg}'
_LOG_DEFAULT = '{created:.7f} [{levelname}] [{name}]: {msg}'
_DESTINATIONS = {'screen', 'log', 'own_log'}
_ALIASES: dict[str, dict[str, set[str]]] = {
    'screen': {'both': {'screen'}},
    'log': {'stdout': {'log'}, 'stderr': {'log', 'screen'}},  # stderr is always seen
    'both': {'both': {'log', 'screen'}},
    'own_log': {'stdout': {'own_log'}, 'stderr': {'own_log'}, 'both': {'own_log'}},
    'full': {'stdout': {'log', 'own_log', 'screen'}, 'stderr': {'log', 'own_log', 'screen'},
             'both': {'own_log'}},
}


def _base_log_dir() -> str:
    configured = os.environ.get('ROS_LOG_DIR')
    if configured:
        return os.path.normpath(os.path.expanduser(configured))
    home = os.environ.get('ROS_HOME') or os.path.join(os.path.expanduser('~'), '.ros')
    return os.path.normpath(os.path.join(os.path.expanduser(home), 'log'))


def _make_unique_log_dir(*, base_path: str) -> str:
    """A new directory `<date-time>-<host>-<pid>` below base_path."""
    stamp = datetime.datetime.now().strftime('%Y-%m-%d-%H-%M-%S-%f')
    path = os.path.join(base_path, f'{stamp}-{socket.gethostname()}-{os.getpid()}')
    os.makedirs(path, exist_ok=True)
    return path


def _renew_latest_log_dir(*, log_dir: str) -> bool:
    """Point `<base>/latest` at log_dir; False when `latest` is something else."""
    latest = os.path.join(os.path.dirname(log_dir), 'latest')
    if os.path.lexists(latest):
        if not os.path.islink(latest):
            return False
        os.unlink(latest)
    os.symlink(log_dir, latest, target_is_directory=True)
    return True


class _ScreenHandler(logging.Handler):
    """Writes to whatever sys.stdout is at the time (pytest swaps it)."""

    def emit(self, record: logging.LogRecord) -> None:
        try:
            sys.stdout.write(self.format(record) + '\n')
            sys.stdout.flush()
        except (BrokenPipeError, ValueError):
            pass  # the reader went away: keep launching, as upstream does


def _formatter(fmt: str, style: str) -> logging.Formatter:
    return logging.Formatter(fmt, style=style)  # type: ignore[arg-type]


def _from_env(name: str) -> str | None:
    value = os.environ.get(name)
    return value.encode('latin1').decode('unicode_escape') if value else None


class LaunchConfig:
    """Where and how launch logs: level, log directory, screen and file formats."""

    def __init__(self) -> None:
        self.reset()

    def reset(self) -> None:
        self._log_dir: str | None = None
        self._file_handlers: dict[str, logging.Handler] = {}
        self._screen_handler: logging.Handler | None = None
        self._log_handler_factory: Callable[..., logging.Handler] | None = None
        self.level = logging.INFO
        self.set_screen_format('default')
        self.set_log_format('default')

    @property
    def level(self) -> int:
        return logging.root.getEffectiveLevel()

    @level.setter
    def level(self, new_level: int) -> None:
        logging.root.setLevel(new_level)

    @property
    def log_dir(self) -> str:
        if self._log_dir is None:
            self._log_dir = _make_unique_log_dir(base_path=_base_log_dir())
            try:
                if not _renew_latest_log_dir(log_dir=self._log_dir):
                    get_logger('launch').warning(
                        'Cannot create a symlink to latest log directory')
            except OSError as error:
                get_logger('launch').warning(
                    f'Cannot create a symlink to latest log directory: {error}')
        return self._log_dir

    @log_dir.setter
    def log_dir(self, new_log_dir: str | None) -> None:
        if self._file_handlers:
            raise RuntimeError('Cannot change the log directory once a log file is open '
                               f'({self._log_dir})')
        if new_log_dir is not None and not os.path.isdir(new_log_dir):
            raise ValueError(f'{new_log_dir} is not a directory')
        self._log_dir = new_log_dir

    @property
    def log_handler_factory(self) -> Callable[..., logging.Handler]:
        if self._log_handler_factory is None:
            return lambda path, encoding=None: logging.FileHandler(path, encoding=encoding,
                                                                   delay=True)
        return self._log_handler_factory

    @log_handler_factory.setter
    def log_handler_factory(self, factory: Callable[..., logging.Handler]) -> None:
        if self._file_handlers:
            raise RuntimeError('Cannot change the log handler factory once a log file is open')
        self._log_handler_factory = factory

    def set_screen_format(self, screen_format: str | None, *, screen_style: str | None = None
                          ) -> None:
        """'default', 'default_with_timestamp', or a format of `screen_style` ('{' if None);
        OVERRIDE_LAUNCH_SCREEN_FORMAT wins over both."""
        override = _from_env('OVERRIDE_LAUNCH_SCREEN_FORMAT')
        if override is not None:
            screen_format, screen_style = override, '{'
        aliases = {'default': _SCREEN_DEFAULT, 'default_with_timestamp': _SCREEN_WITH_TIMESTAMP}
        if screen_format in aliases:
            if screen_style is not None and screen_style != '{':
                raise ValueError(f'Cannot set a custom format style for the "{screen_format}" '
                                 'screen format.')
            screen_format, screen_style = aliases[screen_format], '{'
        self.screen_formatter = _formatter(screen_format or _SCREEN_DEFAULT,
                                           screen_style or '{')
        if self._screen_handler is not None:
            self._screen_handler.setFormatter(self.screen_formatter)

    def set_log_format(self, log_format: str | None, *, log_style: str | None = None) -> None:
        """'default' or a format of `log_style`; OVERRIDE_LAUNCH_LOG_FORMAT wins."""
        override = _from_env('OVERRIDE_LAUNCH_LOG_FORMAT')
        if override is not None:
            log_format, log_style = override, '{'
        if log_format == 'default':
            if log_style is not None and log_style != '{':
                raise ValueError('Cannot set a custom format style for the "default" log '
                                 'format.')
            log_format, log_style = _LOG_DEFAULT, '{'
        self.file_formatter = _formatter(log_format or _LOG_DEFAULT, log_style or '{')

    def get_screen_handler(self) -> logging.Handler:
        if self._screen_handler is None:
            self._screen_handler = _ScreenHandler()
            self._screen_handler.setFormatter(self.screen_formatter)
        return self._screen_handler

    def get_log_file_path(self, file_name: str = 'launch.log') -> str:
        return os.path.join(self.log_dir, file_name)

    def get_log_file_handler(self, file_name: str = 'launch.log') -> logging.Handler:
        """The (one) handler writing to file_name in the log directory."""
        path = self.get_log_file_path(file_name)
        handler = self._file_handlers.get(path)
        if handler is None:
            handler = self.log_handler_factory(path, encoding='utf-8')
            handler.setFormatter(_FileFormatter(self))
            self._file_handlers[path] = handler
        return handler


class _FileFormatter(logging.Formatter):
    """The log file's format of the moment; a process's line is `<time> <line>`."""

    def __init__(self, config: LaunchConfig) -> None:
        super().__init__()
        self.__config = config

    def format(self, record: logging.LogRecord) -> str:
        if getattr(record, 'raw_line', False):
            return f'{record.created:.7f} {record.getMessage()}'
        return self.__config.file_formatter.format(record)


launch_config = LaunchConfig()


def get_logger(name: str | None = None) -> logging.Logger:
    """A logger shown as `[LEVEL] [name]: message` on the screen and in launch.log.

    It has both handlers itself and does not propagate (as upstream's LaunchLogger), so
    'launch.user' is not printed again by 'launch'.
    """
    logger = logging.getLogger(name)
    logger.propagate = False
    for handler in (launch_config.get_screen_handler(), launch_config.get_log_file_handler()):
        if handler not in logger.handlers:
            logger.addHandler(handler)
    return logger


def _destinations(output: str | dict[str, Any]) -> dict[str, set[str]]:
    if isinstance(output, str):
        if output not in _ALIASES:
            raise ValueError(f"output must be one of {sorted(_ALIASES)}, got '{output}'")
        config = _ALIASES[output]
    elif isinstance(output, dict):
        config = output
    else:
        raise ValueError(f'output must be text or a dict, got {type(output).__name__}')
    result: dict[str, set[str]] = {'stdout': set(), 'stderr': set(), 'both': set()}
    for stream, where in config.items():
        if stream not in result:
            raise ValueError(f"output keys are 'stdout', 'stderr' and 'both', got '{stream}'")
        where = {where} if isinstance(where, str) else set(where)
        if not where <= _DESTINATIONS:
            raise ValueError(f'output destinations are {sorted(_DESTINATIONS)}, got '
                             f'{sorted(where)}')
        result[stream] |= where
    return result


def _stream_logger(name: str) -> logging.Logger:
    logger = logging.getLogger(name)
    logger.propagate = False
    for handler in list(logger.handlers):
        logger.removeHandler(handler)
    return logger


def _raw_file_handler(file_name: str) -> logging.Handler:
    handler = launch_config.get_log_file_handler(file_name)
    handler.setFormatter(_formatter('{message}', '{'))
    return handler


class _MainLogFile(logging.Handler):
    """Process output in launch.log: `<time> <line>`."""

    def emit(self, record: logging.LogRecord) -> None:
        launch_config.get_log_file_handler().handle(
            logging.makeLogRecord({**record.__dict__, 'raw_line': True}))


class _RawScreen(_ScreenHandler):
    def __init__(self) -> None:
        super().__init__()
        self.setFormatter(_formatter('{message}', '{'))


def get_output_loggers(process_name: str, output_config: str | dict[str, Any]
                       ) -> tuple[logging.Logger, logging.Logger]:
    """(stdout logger, stderr logger) of a process, routed as `output_config` says."""
    destinations = _destinations(output_config)
    loggers = []
    for stream in ('stdout', 'stderr'):
        logger = _stream_logger(f'{process_name}-{stream}')
        where = destinations[stream] | destinations['both']
        if 'screen' in where:
            logger.addHandler(_RawScreen())
        if 'log' in where:
            logger.addHandler(_MainLogFile())
        if 'own_log' in destinations[stream]:
            logger.addHandler(_raw_file_handler(f'{process_name}-{stream}.log'))
        if 'own_log' in destinations['both']:
            logger.addHandler(_raw_file_handler(f'{process_name}.log'))
        loggers.append(logger)
    return loggers[0], loggers[1]


def reset() -> None:
    """Back to the start: launch's loggers without handlers or levels of their own, level
    INFO, default formats, no log directory yet."""
    for logger in [logging.root, *logging.Logger.manager.loggerDict.values()]:
        if isinstance(logger, logging.Logger) and (logger is logging.root
                                                   or not logger.propagate):
            # propagate is off on the loggers launch configured (get_logger, output loggers)
            if logger is not logging.root:
                logger.setLevel(logging.NOTSET)
            for handler in list(logger.handlers):
                logger.removeHandler(handler)
    launch_config.reset()


def log_launch_config(*, logger: logging.Logger | None = None) -> None:
    logger = logger or get_logger('launch')
    logger.info(f'All log files can be found below {launch_config.log_dir}')
    logger.info(f'Default logging verbosity is set to {logging.getLevelName(launch_config.level)}')


# -- this workspace's shorthands ------------------------------------------------------------
def log_dir() -> str:
    return launch_config.log_dir


def set_level(level: int) -> None:
    launch_config.level = level


def level_name() -> str:
    return logging.getLevelName(launch_config.level)


def start_log_file() -> None:
    """Open launch.log now (a launch says where it is as it starts)."""
    get_logger('launch')
