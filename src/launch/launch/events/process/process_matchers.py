"""Process matchers for ProcessTargetedEvent: by pid, by name, by executable."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def _matcher(test: Callable[[dict[str, Any]], bool]) -> Callable[[Any], bool]:
    def matcher(action: Any) -> bool:
        details = getattr(action, 'process_details', None)
        return details is not None and test(details)  # None: not started yet
    return matcher


def matches_pid(pid: int) -> Callable[[Any], bool]:
    return _matcher(lambda details: details['pid'] == pid)


def matches_name(name: str) -> Callable[[Any], bool]:
    return _matcher(lambda details: details['name'] == name)


def matches_executable(executable: str) -> Callable[[Any], bool]:
    return _matcher(lambda details: details['cmd'][0].endswith(executable))
