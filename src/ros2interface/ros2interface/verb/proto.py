"""ros2 interface proto: Output an interface prototype."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import CliError, VerbContext

from ros2interface.api import KINDS

HELP = 'Output an interface prototype'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('type', help="Show an interface prototype (e.g. 'std_msgs/msg/String')")
    parser.add_argument('--no-quotes', action='store_true',
                        help='if true output has no outer quotes.')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    from ros2cli.interface_types import import_type

    from rosidl_runtime_py import message_to_yaml
    parts = args.type.split('/')
    kind = parts[1] if len(parts) == 3 else None
    interface = None
    for candidate in ([kind] if kind else KINDS):
        try:
            interface = import_type(args.type, candidate)
            break
        except ValueError:
            continue
    if interface is None:
        raise CliError('The passed interface type is invalid')
    if hasattr(interface, 'Goal'):
        instance = interface.Goal()
    elif hasattr(interface, 'Request'):
        instance = interface.Request()
    else:
        instance = interface()
    text = message_to_yaml(instance)
    print(text if args.no_quotes else f'"{text}"', file=context.stdout)
    return 0
