"""assertInStdout / assertInStderr / assertInStream: text a launched process printed."""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

from launch_testing.tools.text import build_text_match
from launch_testing.util import resolveProcesses

__unittest = True  # failures point at the test's line, not at this module (unittest's rule)

_ANSI_ESCAPE = re.compile(r'\x1b\[[0-9;?]*[ -/]*[@-~]')


def stream_text(proc_output: Any, process: Any, stream: str,
                strip_ansi_escape_sequences: bool = True) -> str:
    """All that `process` wrote to `stream` ('stdout' or 'stderr'), as one str."""
    if stream not in ('stdout', 'stderr'):
        raise ValueError(f"stream must be 'stdout' or 'stderr', got '{stream}'")
    from_stdout = stream == 'stdout'
    text = ''.join(event.text.decode(errors='replace') for event in proc_output[process]
                   if event.from_stdout == from_stdout)
    return _ANSI_ESCAPE.sub('', text) if strip_ansi_escape_sequences else text


def assertInStream(proc_output: Any, expected_output: Any,
                   process: Any, cmd_args: Any = None, *,
                   output_filter: Callable[[str], str] | None = None,
                   strict_proc_matching: bool = True, strip_ansi_escape_sequences: bool = True,
                   stream: str = 'stderr') -> None:
    if output_filter is not None and not callable(output_filter):
        raise ValueError('output_filter is not callable')
    processes = resolveProcesses(proc_output, process=process, cmd_args=cmd_args,
                                 strict_proc_matching=strict_proc_matching)
    match = build_text_match(expected_output)
    for candidate in processes:
        text = stream_text(proc_output, candidate, stream, strip_ansi_escape_sequences)
        if output_filter is not None:
            text = output_filter(text)
        if match(text) is not None:
            return
    names = ', '.join(sorted(p.process_details['name'] for p in processes))
    raise AssertionError(f"Did not find '{expected_output}' in output for any of the "
                         f'matching processes: {names}')


def assertInStdout(proc_output: Any, expected_output: Any,
                   process: Any, cmd_args: Any = None, *,
                   output_filter: Callable[[str], str] | None = None,
                   strict_proc_matching: bool = True,
                   strip_ansi_escape_sequences: bool = True) -> None:
    assertInStream(proc_output, expected_output, process, cmd_args,
                   output_filter=output_filter, strict_proc_matching=strict_proc_matching,
                   strip_ansi_escape_sequences=strip_ansi_escape_sequences, stream='stdout')


def assertInStderr(proc_output: Any, expected_output: Any,
                   process: Any, cmd_args: Any = None, *,
                   output_filter: Callable[[str], str] | None = None,
                   strict_proc_matching: bool = True,
                   strip_ansi_escape_sequences: bool = True) -> None:
    assertInStream(proc_output, expected_output, process, cmd_args,
                   output_filter=output_filter, strict_proc_matching=strict_proc_matching,
                   strip_ansi_escape_sequences=strip_ansi_escape_sequences, stream='stderr')


def assertDefaultStream() -> str:
    """The stream assertInStream looks at by default (ROS logs go to stderr)."""
    return 'stderr'
