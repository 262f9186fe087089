"""ros2run's API: find a package's executable (ros2pkg.api's lookup) and run it as `ros2 run`
does, the child in the foreground, its exit code returned."""

from __future__ import annotations

import os
import shlex
import signal
import subprocess

from ros2cli.verb_context import CliError, VerbContext
from ros2pkg.api import executables


def run_executable(package: str, executable: str, argv: list[str], prefix: str | None,
                   context: VerbContext) -> int | str:
    lib, available = executables(package)
    paths = [p for p in available if os.path.basename(p) == executable]
    if not paths:
        names = sorted({os.path.basename(p) for p in available})
        listing = ('\n'.join(f'  {n}' for n in names) if names
                   else f'  (none: {lib} holds no executable files)')
        raise CliError(f"No executable found\nPackage '{package}' has these executables:\n"
                       f'{listing}')
    if len(paths) > 1:
        raise CliError('Multiple executables found:\n' + '\n'.join(f'- {p}' for p in paths))
    command = [paths[0], *argv]
    if prefix is not None:
        command = shlex.split(prefix) + command
    try:
        process = subprocess.Popen(command)
    except OSError as error:
        raise CliError(f'Failed to start {command[0]}: {error.strerror}') from None
    # A `kill` of ros2 run reaches the child too instead of leaving it orphaned.
    signal.signal(signal.SIGTERM, lambda signum, _frame: process.send_signal(signum))
    while process.returncode is None:
        try:
            process.wait()
        except KeyboardInterrupt:
            # The child got the same Ctrl-C (same process group): wait for it to finish.
            continue
    code = process.returncode
    if code != 0:
        if code < 0 and -code in signal.valid_signals():
            print(f'[ros2run]: {signal.strsignal(-code)}', file=context.stdout)
        else:
            print(f'[ros2run]: Process exited with failure {code}', file=context.stdout)
    return code
