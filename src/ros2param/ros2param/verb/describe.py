"""ros2 param describe: Show descriptive information about declared parameters."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2param.api import TYPE_NAMES, call, find_node

HELP = 'Show descriptive information about declared parameters'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('node_name', help='Name of the ROS node')
    parser.add_argument('parameter_names', nargs='+', help='Names of the parameters')


def runs_in_daemon(_args: argparse.Namespace) -> bool:
    """One exchange with the node: the daemon may run it for the CLI (ros2cli.daemon.verb_host)."""
    return True


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rcl_interfaces.srv import DescribeParameters
    from ros2cli.node.direct import cli_node
    target = find_node(args, context=context)
    if target is None:
        return 'Node not found'
    with cli_node(context, spin_time=args.spin_time) as node:
        response = call(node, DescribeParameters, f'{target}/describe_parameters',
                         DescribeParameters.Request(names=args.parameter_names), context=context)
    for descriptor in response.descriptors:
        print('Parameter name:', descriptor.name, file=context.stdout)
        print('  Type:', TYPE_NAMES.get(descriptor.type, 'unknown type'), file=context.stdout)
        if descriptor.description:
            print('  Description:', descriptor.description, file=context.stdout)
        ranges = list(descriptor.floating_point_range) + list(descriptor.integer_range)
        print(
            '  Constraints:', file=context.stdout
        )  # always, as ros2param prints it (empty when there are none)
        if descriptor.read_only:
            print('    Read only: true', file=context.stdout)
        if ranges:
            print('    Min value:', ranges[0].from_value, file=context.stdout)
            print('    Max value:', ranges[0].to_value, file=context.stdout)
            if ranges[0].step:
                print('    Step:', ranges[0].step, file=context.stdout)
        if descriptor.additional_constraints:
            print(
                '    Additional constraints:',
                descriptor.additional_constraints,
                file=context.stdout,
            )
    return 0
