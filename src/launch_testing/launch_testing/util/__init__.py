"""launch_testing.util: process look-up for the asserts, and KeepAliveProc."""

from __future__ import annotations

import sys

from launch.actions import ExecuteProcess

from launch_testing.util.proc_lookup import (
    NO_CMD_ARGS,
    NoMatchingProcessException,
    resolveProcesses,
)

_KEEP_ALIVE = '''
import time
try:
    while True:
        time.sleep(1)
except KeyboardInterrupt:
    pass
'''


def KeepAliveProc() -> ExecuteProcess:
    """A process that runs until the launch stops it: keeps the launch alive for the tests."""
    return ExecuteProcess(cmd=[sys.executable, '-c', _KEEP_ALIVE])


__all__ = ['NO_CMD_ARGS', 'KeepAliveProc', 'NoMatchingProcessException', 'resolveProcesses']
