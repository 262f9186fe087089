"""ros2 launch <package> <launch file> [name:=value ...] | ros2 launch <path> [...]"""

from __future__ import annotations

import argparse
import os
import sys

from ros2cli.verb_context import CliError, VerbContext

from ros2launch.api import (
    MultipleLaunchFilesError,
    get_share_file_path_from_package,
    launch_a_launch_file,
    print_a_launch_file,
    print_arguments_of_launch_file,
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        '-n', '--noninteractive', default=not sys.stdin.isatty(), action='store_true',
        help='Run the launch system non-interactively, with no terminal associated')
    parser.add_argument(
        '-d', '--debug', default=False, action='store_true',
        help='Put the launch system in debug mode, provides more verbose output.')
    group = parser.add_mutually_exclusive_group()
    group.add_argument(
        '-p', '--print', '--print-description', default=False, action='store_true',
        help='Print the launch description to the console without launching it.')
    group.add_argument(
        '-s', '--show-args', '--show-arguments', default=False, action='store_true',
        help='Show arguments that may be given to the launch file.')
    parser.add_argument(
        '-a', '--show-all-subprocesses-output', default=False, action='store_true',
        help="Show all launched subprocesses' output by overriding their output configuration "
             'using the OVERRIDE_LAUNCH_PROCESS_OUTPUT envvar.')
    parser.add_argument(
        '--launch-prefix',
        help='Prefix command, which should go before all executables. Command must be wrapped '
             "in quotes if it contains spaces (e.g. --launch-prefix 'xterm -e gdb -ex run "
             "--args').")
    parser.add_argument(
        '--launch-prefix-filter',
        help='Regex pattern for filtering which executables the --launch-prefix is applied to '
             'by matching the executable name.')
    parser.add_argument('package_name',
                        help='Name of the ROS package which contains the launch file')
    parser.add_argument('launch_file_name', nargs='?', help='Name of the launch file')
    parser.add_argument(
        'launch_arguments', nargs='*',
        help="Arguments to the launch file; '<name>:=<value>' (for duplicates, last one wins)")
    parser.set_defaults(_main=main)


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from launch.launch_description_sources import InvalidLaunchFileError
    arguments: list[str] = []
    if os.path.isfile(args.package_name):
        path = args.package_name
        if args.launch_file_name is not None:
            # With a path, the "launch file" word is the first launch argument.
            arguments.append(args.launch_file_name)
    elif args.launch_file_name is None:
        return 'No launch file supplied'
    else:
        from ament_index_python.packages import PackageNotFoundError
        try:
            path = get_share_file_path_from_package(package_name=args.package_name,
                                                    file_name=args.launch_file_name)
        except PackageNotFoundError as error:
            raise CliError(f"Package '{args.package_name}' not found: {error}") from None
        except (FileNotFoundError, MultipleLaunchFilesError) as error:
            raise CliError(str(error)) from None
    arguments.extend(args.launch_arguments)
    if args.launch_prefix is None and args.launch_prefix_filter is not None:
        raise CliError('--launch-prefix must be specified if --launch-prefix-filter is provided')
    # As launch arguments, last: they win over a `launch-prefix:=` given by hand.
    if args.launch_prefix:
        arguments.append(f'launch-prefix:={args.launch_prefix}')
    if args.launch_prefix_filter:
        arguments.append(f'launch-prefix-filter:={args.launch_prefix_filter}')
    if args.show_all_subprocesses_output:
        os.environ['OVERRIDE_LAUNCH_PROCESS_OUTPUT'] = 'both'
    try:
        if args.print:
            print_a_launch_file(launch_file_path=path)
            return 0
        if args.show_args:
            print_arguments_of_launch_file(launch_file_path=path)
            return 0
        return launch_a_launch_file(launch_file_path=path, launch_file_arguments=arguments,
                                    noninteractive=args.noninteractive, debug=args.debug)
    except (InvalidLaunchFileError, ValueError) as error:
        raise CliError(str(error)) from None
