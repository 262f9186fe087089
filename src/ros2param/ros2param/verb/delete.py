"""ros2 param delete: Delete parameter."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2param.api import add_timeout, call, find_node, print_result

HELP = 'Delete parameter'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('node_name', help='Name of the ROS node')
    parser.add_argument('parameter_name', help='Name of the parameter')
    add_timeout(parser)


def runs_in_daemon(_args: argparse.Namespace) -> bool:
    """One exchange with the node: the daemon may run it for the CLI (ros2cli.daemon.verb_host)."""
    return True


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rcl_interfaces.msg import Parameter, ParameterValue
    from rcl_interfaces.srv import SetParameters
    from ros2cli.node.direct import cli_node
    target = find_node(args, context=context)
    if target is None:
        return 'Node not found'
    with cli_node(context, spin_time=args.spin_time) as node:
        request = SetParameters.Request(
            parameters=[Parameter(name=args.parameter_name, value=ParameterValue())])
        response = call(node, SetParameters, f'{target}/set_parameters', request, context=context)
    print_result(response.results[0], 'Deleted parameter successfully',
                  'Deleting parameter failed', context=context)
    return 0
