"""ros2 run [--prefix CMD] <package> <executable> [args...]"""

from __future__ import annotations

import argparse
import os
import shlex
import signal
import subprocess

from ros2cli_lite.api import CliError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('--prefix', metavar='PREFIX',
                        help='Prefix command, which should go before the executable. Command '
                        'must be wrapped in quotes if it contains spaces (e.g. --prefix '
                        "'gdb -ex run --args').")
    parser.add_argument('package_name', help='Name of the ROS package')
    parser.add_argument('executable_name', help='Name of the executable')
    parser.add_argument('argv', nargs=argparse.REMAINDER,
                        help='Pass arbitrary arguments to the executable')
    parser.set_defaults(_main=lambda args: run(args.package_name, args.executable_name,
                                               args.argv, args.prefix))


def main_argv(argv: list[str]) -> int | str:
    """Parse `ros2 run` arguments by hand: everything after the executable is the child's."""
    prefix = None
    rest = list(argv)
    while rest and rest[0].startswith('-'):
        option = rest.pop(0)
        if option in ('-h', '--help'):
            parser = argparse.ArgumentParser(prog='ros2 run',
                                             description='Run a package specific executable')
            add_arguments(parser)
            parser.print_help()
            return 0
        if option == '--prefix':
            if not rest:
                return _usage('argument --prefix: expected one argument')
            prefix = rest.pop(0)
        elif option.startswith('--prefix='):
            prefix = option.split('=', 1)[1]
        else:
            return _usage(f'unrecognized arguments: {option}')
    if len(rest) < 2:
        return _usage('the following arguments are required: package_name, executable_name'
                      if not rest else 'the following arguments are required: executable_name')
    return run(rest[0], rest[1], rest[2:], prefix)


def _usage(message: str) -> int:
    import sys
    print('usage: ros2 run [-h] [--prefix PREFIX] package_name executable_name ...\n'
          f'ros2 run: error: {message}', file=sys.stderr)
    return 2


def executables(package: str) -> tuple[str, list[str]]:
    """(lib dir, every executable file under lib/<package>/, recursively)."""
    from ament_index_python.packages import PackageNotFoundError, get_package_prefix
    try:
        prefix = get_package_prefix(package)
    except (PackageNotFoundError, ValueError):
        raise CliError(f"Package '{package}' not found") from None
    lib = os.path.join(prefix, 'lib', package)
    found = []
    for directory, _, files in os.walk(lib, followlinks=True):
        for name in files:
            path = os.path.join(directory, name)
            if os.path.isfile(path) and os.access(path, os.X_OK):
                found.append(path)
    return lib, sorted(found)


def run(package: str, executable: str, argv: list[str], prefix: str | None) -> int | str:
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
            print(f'[ros2run]: {signal.strsignal(-code)}')
        else:
            print(f'[ros2run]: Process exited with failure {code}')
    return code
