"""resolveProcesses: the ExecuteProcess actions a process argument of an assert means."""

from __future__ import annotations

from typing import Any

from launch.actions import ExecuteLocal
from launch.substitutions import TextSubstitution

NO_CMD_ARGS = object()  # cmd_args meaning "started without arguments"


class NoMatchingProcessException(Exception):
    pass


def _describe(process: Any) -> str:
    details = getattr(process, 'process_details', None)
    if details:
        return ' '.join([details['name'], *details['cmd'][1:]])
    # Not launched: its command when it is plain text (upstream's message otherwise).
    description = getattr(process, 'process_description', None)
    cmd = getattr(description, 'cmd', None) or getattr(process, 'cmd', None) or []
    if all(isinstance(sub, TextSubstitution) for part in cmd for sub in part):
        return ' '.join(''.join(sub.text for sub in part) for part in cmd)
    return 'Unknown - Process not launched yet'


def _matches(process: Any, name: str, cmd_args: list[str] | object | None) -> bool:
    details = process.process_details
    if name not in details['name']:
        return False
    if cmd_args is None:
        return True
    if cmd_args is NO_CMD_ARGS:
        return len(details['cmd']) == 1
    return all(arg in details['cmd'][1:] for arg in cmd_args)  # type: ignore[union-attr]


def resolveProcesses(info_obj: Any, *, process: Any = None,
                     cmd_args: Any = None, strict_proc_matching: bool = True) -> list[Any]:
    """Match `process` (None: all, an ExecuteProcess, or part of a process name) in info_obj.

    Raises NoMatchingProcessException naming the known processes when nothing matches, and
    (strict_proc_matching) when a name matches more than one process.
    """
    known = list(info_obj.processes())
    if process is None:
        if not known:
            raise NoMatchingProcessException('No data recorded for any process')
        return known
    if isinstance(process, ExecuteLocal):  # ExecuteProcess is one
        if process in known:
            return [process]
        raise NoMatchingProcessException(f'No data recorded for proc {_describe(process)}')
    if not isinstance(process, str):
        raise TypeError(f"proc argument must be 'ExecuteLocal' or 'str' not {type(process)}")
    if isinstance(cmd_args, str):
        cmd_args = [cmd_args]
    matches = [candidate for candidate in known if _matches(candidate, process, cmd_args)]
    names = ', '.join(sorted(_describe(candidate) for candidate in known))
    if not matches:
        raise NoMatchingProcessException(
            f"Did not find any processes matching name '{process}' and args '{cmd_args}'. "
            f'Procs: {names}')
    if strict_proc_matching and len(matches) > 1:
        raise Exception(
            f"Found multiple processes matching name '{process}' and cmd_args '{cmd_args}'. "
            f'Procs: {names}')
    return matches
