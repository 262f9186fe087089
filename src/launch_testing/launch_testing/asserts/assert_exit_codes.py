"""assertExitCodes: every (or the named) launched process exited with an allowed code."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launch_testing.util import resolveProcesses

__unittest = True  # failures point at the test's line, not at this module (unittest's rule)

EXIT_OK = 0
EXIT_FORCED = 1
EXIT_SIGINT = 130
EXIT_SIGQUIT = 131
EXIT_SIGKILL = 137
EXIT_SIGSEGV = 139


def assertExitCodes(proc_info: Any,
                    allowable_exit_codes: Iterable[int] = (EXIT_OK,), process: Any = None,
                    cmd_args: Any = None, *, strict_proc_matching: bool = True) -> None:
    allowed = list(allowable_exit_codes)
    for code in allowed:
        assert isinstance(code, int), f'Provided exit code {code} is not an int'
    for action in resolveProcesses(proc_info, process=process, cmd_args=cmd_args,
                                   strict_proc_matching=strict_proc_matching):
        info = proc_info[action]
        returncode = getattr(info, 'returncode', None)
        assert returncode is not None, f'Proc {info.process_name} is still running'
        assert returncode in allowed, (
            f'Proc {info.process_name} exited with code {returncode} '
            f"(allowed: {', '.join(map(str, allowed))}; cmd: {' '.join(info.cmd)})")
