"""launch_testing.asserts: exit codes and output of the launched processes."""

from launch_testing.asserts.assert_exit_codes import (
    EXIT_FORCED,
    EXIT_OK,
    EXIT_SIGINT,
    EXIT_SIGKILL,
    EXIT_SIGQUIT,
    EXIT_SIGSEGV,
    assertExitCodes,
)
from launch_testing.asserts.assert_output import (
    assertDefaultStream,
    assertInStderr,
    assertInStdout,
    assertInStream,
)
from launch_testing.asserts.assert_sequential_output import (
    SequentialTextChecker,
    assertSequentialStdout,
)
from launch_testing.util.proc_lookup import NO_CMD_ARGS

__all__ = [
    'EXIT_FORCED', 'EXIT_OK', 'EXIT_SIGINT', 'EXIT_SIGKILL', 'EXIT_SIGQUIT', 'EXIT_SIGSEGV',
    'NO_CMD_ARGS', 'SequentialTextChecker', 'assertDefaultStream', 'assertExitCodes',
    'assertInStderr', 'assertInStdout', 'assertInStream', 'assertSequentialStdout',
]
