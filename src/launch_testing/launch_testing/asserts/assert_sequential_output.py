"""assertSequentialStdout: pieces of one process's output, in the order given."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from launch_testing.util import resolveProcesses

__unittest = True  # failures point at the test's line, not at this module (unittest's rule)


class SequentialTextChecker:
    """Each assertInStdout must find its text after where the previous one matched."""

    def __init__(self, output: list[str]) -> None:
        self._output = output
        self._index = 0  # chunk of output the last match was in
        self._offset = 0  # position in that chunk after the last match

    def assertInText(self, msg: str) -> None:
        self.assertInStdout(msg)

    def assertInStdout(self, msg: str) -> None:
        offset = self._offset
        for index in range(self._index, len(self._output)):
            found = self._output[index].find(msg, offset)
            if found != -1:
                self._index, self._offset = index, found + len(msg)
                return
            offset = 0
        raise AssertionError(f"'{msg}' not found in sequence after previous match.  The output "
                             f'near the last matched line:\n{self.get_nearby_lines()}')

    def get_nearby_lines(self) -> str:
        """The text around where the last match ended: back to the third line end before
        it, on to the third line end after it (upstream's window)."""
        first = max(0, self._index - 2)
        window = ''.join(self._output[first:self._index + 4])
        here = sum(len(chunk) for chunk in self._output[first:self._index]) + self._offset
        start = here
        for _ in range(3):
            start = max(window.rfind('\n', 0, start), 0)
        start = start + 1 if start else 0
        end = here
        for _ in range(3):
            found = window.find('\n', end + 1)
            end = found if found != -1 else end
        return window[start:end]


@contextmanager
def assertSequentialStdout(proc_output: Any, process: Any,
                           cmd_args: Any = None) -> Iterator[SequentialTextChecker]:
    """The output of one process (names matching several processes are refused)."""
    action = resolveProcesses(proc_output, process=process, cmd_args=cmd_args,
                              strict_proc_matching=True)[0]
    yield SequentialTextChecker([event.text.decode(errors='replace')
                                 for event in proc_output[action]])
