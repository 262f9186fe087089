"""ros2 run [--prefix CMD] <package> <executable> [args...]"""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2run.api import run_executable


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('--prefix', metavar='PREFIX',
                        help='Prefix command, which should go before the executable. Command '
                        'must be wrapped in quotes if it contains spaces (e.g. --prefix '
                        "'gdb -ex run --args').")
    parser.add_argument('package_name', help='Name of the ROS package')
    parser.add_argument('executable_name', help='Name of the executable')
    parser.add_argument('argv', nargs=argparse.REMAINDER,
                        help='Pass arbitrary arguments to the executable')
    parser.set_defaults(_main=lambda args, context: run_executable(
        args.package_name, args.executable_name, args.argv, args.prefix, context))


def main_argv(argv: list[str], context: VerbContext) -> int | str:
    """Parse `ros2 run` arguments by hand: everything after the executable is the child's."""
    prefix = None
    rest = list(argv)
    while rest and rest[0].startswith('-'):
        option = rest.pop(0)
        if option in ('-h', '--help'):
            parser = argparse.ArgumentParser(prog='ros2 run',
                                             description='Run a package specific executable')
            add_arguments(parser)
            parser.print_help(context.stdout)
            return 0
        if option == '--prefix':
            if not rest:
                return _usage('argument --prefix: expected one argument', context)
            prefix = rest.pop(0)
        elif option.startswith('--prefix='):
            prefix = option.split('=', 1)[1]
        else:
            return _usage(f'unrecognized arguments: {option}', context)
    if len(rest) < 2:
        return _usage('the following arguments are required: package_name, executable_name'
                      if not rest else 'the following arguments are required: executable_name',
                      context)
    return run_executable(rest[0], rest[1], rest[2:], prefix, context)


def _usage(message: str, context: VerbContext) -> int:
    print('usage: ros2 run [-h] [--prefix PREFIX] package_name executable_name ...\n'
          f'ros2 run: error: {message}', file=context.stderr)
    return 2
