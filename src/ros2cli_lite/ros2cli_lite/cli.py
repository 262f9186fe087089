"""`ros2 <command> <verb> ...`: parse the command line and dispatch to the command modules."""

from __future__ import annotations

import argparse
import importlib
import signal
import sys

from ros2cli_lite.api import CliError

COMMANDS = {
    'interface': 'Show information about ROS interfaces',
    'node': 'Various node related sub-commands',
    'param': 'Various param related sub-commands',
    'run': 'Run a package specific executable',
    'service': 'Various service related sub-commands',
    'topic': 'Various topic related sub-commands',
}


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog='ros2', description='ros2 is an extensible command-line tool for ROS 2.',
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--use-python-default-buffering', action='store_true',
                        help='Do not force line buffering in stdout (accepted, no effect)')
    sub = parser.add_subparsers(title='Commands', dest='_command', metavar='Call')
    for name, help_text in COMMANDS.items():
        module = importlib.import_module(f'ros2cli_lite.command.{name}')
        command = sub.add_parser(name, help=help_text, description=help_text)
        module.add_arguments(command)
    return parser


def main(argv: list[str] | None = None) -> int | str:
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] == 'run':
        # `ros2 run` passes everything after the executable through untouched.
        from ros2cli_lite.command import run
        return _guard(lambda: run.main_argv(argv[1:]))
    parser = build_parser()
    args = parser.parse_args(argv)
    if args._command is None:
        parser.print_help()
        return 0
    func = getattr(args, '_main', None)
    if getattr(args, 'spin_time', None) is not None:
        from ros2cli_lite import api
        api.SPIN_TIME = max(0.0, args.spin_time)
    if func is None:
        parser.parse_args([args._command, '--help'])
        return 0
    return _guard(lambda: func(args))


def _guard(call) -> int:
    try:
        result = call()
    except CliError as error:
        print(str(error), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return int(signal.SIGINT)
    except BrokenPipeError:
        # The reader went away (`ros2 ... | head`): stop quietly, as a shell tool does.
        import os
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    if isinstance(result, str):
        print(result, file=sys.stderr)
        return 1
    return result or 0
