"""`ros2 <command> <verb> ...`: parse the command line and dispatch to the command modules.

Commands come from the ament index, as ros2cli's come from entry points: a package adds a
command by installing `share/ament_index/resource_index/ros2cli.command/<name>`, whose
first line is the module (with `add_arguments(parser)`, verbs setting `_main`) and whose
second line is the help text. Only the invoked command's module is imported, so a verb pays
for nothing it does not use.
"""

from __future__ import annotations

import argparse
import importlib
import os
import signal
import sys

from ros2cli.verb_context import CliError, VerbContext, run_main

RESOURCE_TYPE = 'ros2cli.command'


def registered_commands() -> dict[str, tuple[str, str]]:
    """{command: (module, help)} from the ament index; the first prefix to name one wins."""
    commands: dict[str, tuple[str, str]] = {}
    for prefix in os.environ.get('AMENT_PREFIX_PATH', '').split(os.pathsep):
        directory = os.path.join(prefix, 'share', 'ament_index', 'resource_index', RESOURCE_TYPE)
        try:
            names = os.listdir(directory)
        except OSError:
            continue
        for name in names:
            if name in commands or name.startswith('.'):
                continue
            with open(os.path.join(directory, name), encoding='utf-8') as resource:
                lines = resource.read().splitlines()
            if lines:
                commands[name] = (lines[0].strip(), lines[1].strip() if len(lines) > 1 else '')
    return dict(sorted(commands.items()))


def build_parser(commands: dict[str, tuple[str, str]], only: str | None = None
                 ) -> argparse.ArgumentParser:
    """The `ros2` parser; with `only`, the other commands get no verbs (nothing imported)."""
    parser = argparse.ArgumentParser(
        prog='ros2', description='ros2 is an extensible command-line tool for ROS 2.',
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--use-python-default-buffering', action='store_true',
                        help='Do not force line buffering in stdout (accepted, no effect)')
    sub = parser.add_subparsers(title='Commands', dest='_command', metavar='Call')
    for name, (module_name, help_text) in commands.items():
        command = sub.add_parser(name, help=help_text, description=help_text)
        if only in (None, name):
            importlib.import_module(module_name).add_arguments(command)
    return parser


def main(argv: list[str] | None = None) -> int | str:
    # Ctrl-C is a KeyboardInterrupt again from here on (the package's start-up handler ends
    # the process instead), and ends every command with ros2cli's exit code 2, no traceback.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        return _dispatch(sys.argv[1:] if argv is None else argv)
    except KeyboardInterrupt:
        return int(signal.SIGINT)


def _dispatch(argv: list[str]) -> int | str:
    """Parse argv once; run the verb here, or have the daemon run it (verb_client.py)."""
    commands = registered_commands()
    if argv and argv[0] in commands:
        # A command that parses its own arguments (`ros2 run` passes everything after the
        # executable through untouched) has `main_argv(argv, context)`.
        module = importlib.import_module(commands[argv[0]][0])
        main_argv = getattr(module, 'main_argv', None)
        if main_argv is not None:
            return _guard(lambda: main_argv(argv[1:], VerbContext.here()))
    wanted = next((word for word in argv if not word.startswith('-')), None)
    parser = build_parser(commands, only=wanted if wanted in commands else None)
    args = parser.parse_args(argv)
    if args._command is None:
        parser.print_help()
        return 0
    func = getattr(args, '_main', None)
    if func is None:
        parser.parse_args([args._command, '--help'])
        return 0
    if _runs_in_daemon(func, args):
        from ros2cli.daemon.verb_client import run_in_daemon
        code = run_in_daemon(func, args)
        if code is not None:
            return code
    return _guard(lambda: run_main(func, args, VerbContext.here()))


def _runs_in_daemon(func, args: argparse.Namespace) -> bool:
    """Whether the verb's module lets the daemon run it with these arguments (a one-shot verb
    that reads no standard input and no relative path), and --no-daemon was not given."""
    check = getattr(sys.modules.get(func.__module__), 'runs_in_daemon', None)
    return check is not None and not getattr(args, 'no_daemon', False) and bool(check(args))


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
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    if isinstance(result, str):
        print(result, file=sys.stderr)
        return 1
    return result or 0
