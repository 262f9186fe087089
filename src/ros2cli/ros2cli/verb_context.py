"""What a verb gets and gives back: VerbContext in, an exit code or CliError out.

A verb module (`<package>/verb/<verb>.py`) has HELP, add_arguments(parser),
main(args, context) and, when the daemon may run it for the CLI, runs_in_daemon(args). What a
verb needs from where it runs arrives in `context` (VerbContext): the streams it prints to, the
CLI's pid, and in the daemon the daemon's rclpy context and whether the CLI has left. The same
code runs in the CLI and in the daemon (ros2cli.daemon.verb_host); nothing is read from
thread-local or process-wide state. Imports nothing heavy: `ros2` loads it on every call.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TextIO

if TYPE_CHECKING:  # not imported at run time: `ros2` imports this module on every call
    import threading


class CliError(Exception):
    """A verb failed: the message goes to stderr and `ros2` exits with 1."""


class VerbContext:
    """Where a verb runs: passed to every verb's main(args, context) and on to what it calls.

    In the CLI: the process's own streams and pid (`VerbContext.here()`). In the daemon, for a
    CLI: streams that write to that CLI's terminal, the CLI's pid (the verb's node is
    `_ros2cli_<pid>`, as if the CLI had made it), the daemon's rclpy context (its participant
    has met the graph long ago) and the event set when the CLI leaves or presses Ctrl-C.
    """

    def __init__(self, stdout: TextIO, stderr: TextIO, pid: int, ros_context: Any = None,
                 cancelled: threading.Event | None = None) -> None:
        self.stdout = stdout
        self.stderr = stderr
        self.pid = pid
        self.ros_context = ros_context
        self.cancelled = cancelled
        self._interrupted = False

    @classmethod
    def here(cls) -> VerbContext:
        """This process's streams and pid: a verb run by the CLI itself (or by a tool)."""
        return cls(sys.stdout, sys.stderr, os.getpid())

    @property
    def in_daemon(self) -> bool:
        """Whether the daemon runs the verb for a CLI (its node is the daemon's participant)."""
        return self.ros_context is not None

    def check_cancelled(self) -> None:
        """KeyboardInterrupt once after the CLI has left or pressed Ctrl-C: the verb ends as on
        one SIGINT (send_goal still waits for its cancel). Called by every wait of a verb."""
        if self.cancelled is not None and self.cancelled.is_set() and not self._interrupted:
            self._interrupted = True
            raise KeyboardInterrupt


def run_main(func: Callable[..., Any], args: Any, context: VerbContext) -> int:
    """Run a verb's main(args, context) as `ros2` does: a CliError or a returned string is one
    line on the verb's stderr and exit code 1; None is 0."""
    try:
        result = func(args, context)
    except CliError as error:
        print(str(error), file=context.stderr)
        return 1
    if isinstance(result, str):
        print(result, file=context.stderr)
        return 1
    return result or 0
