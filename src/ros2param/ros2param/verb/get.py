"""ros2 param get: Get parameter."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2param.api import call, find_node

HELP = 'Get parameter'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('node_name', help='Name of the ROS node')
    parser.add_argument('parameter_name', help='Name of the parameter')
    parser.add_argument('--hide-type', action='store_true', help='Hide the type information')


LABELS = {
    1: ('Boolean value is:', 'bool_value'), 2: ('Integer value is:', 'integer_value'),
    3: ('Double value is:', 'double_value'), 4: ('String value is:', 'string_value'),
    5: ('Byte values are:', 'byte_array_value'), 6: ('Boolean values are:', 'bool_array_value'),
    7: ('Integer values are:', 'integer_array_value'),
    8: ('Double values are:', 'double_array_value'),
    9: ('String values are:', 'string_array_value'),
}


def runs_in_daemon(_args: argparse.Namespace) -> bool:
    """One exchange with the node: the daemon may run it for the CLI (ros2cli.daemon.verb_host)."""
    return True


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rcl_interfaces.srv import GetParameters
    from ros2cli.node.direct import cli_node
    target = find_node(args, context=context)
    if target is None:
        return 'Node not found'
    with cli_node(context, spin_time=args.spin_time) as node:
        response = call(node, GetParameters, f'{target}/get_parameters',
                         GetParameters.Request(names=[args.parameter_name]), context=context)
    if not response.values:
        return 'Parameter not set'
    value = response.values[0]
    if value.type == 0:
        print('Parameter not set.' if not args.hide_type else None, file=context.stdout)
        return 0
    if value.type not in LABELS:
        return f"Unknown parameter type '{value.type}'"
    label, attribute = LABELS[value.type]
    data = getattr(value, attribute)
    if value.type >= 5:
        data = list(data) if value.type != 5 else [bytes([b]) if isinstance(b, int) else b
                                                   for b in data]
    print(data if args.hide_type else f'{label} {data}', file=context.stdout)
    return 0
