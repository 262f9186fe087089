"""ros2 param set: Set parameter."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2param.api import add_timeout, call, find_node, print_result

HELP = 'Set parameter'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('node_name', help='Name of the ROS node')
    parser.add_argument('parameter_name', help='Name of the parameter')
    parser.add_argument('value', help='Value of the parameter')
    add_timeout(parser)


def parameter_value(text: str):
    """A ParameterValue from a command-line string, typed as YAML reads it (as ros2cli)."""
    import yaml
    from rcl_interfaces.msg import ParameterValue
    value = ParameterValue()
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError:
        data = text
    if isinstance(data, bool):
        value.type, value.bool_value = 1, data
    elif isinstance(data, int):
        value.type, value.integer_value = 2, data
    elif isinstance(data, float):
        value.type, value.double_value = 3, data
    elif isinstance(data, list) and all(isinstance(v, bool) for v in data):
        value.type, value.bool_array_value = 6, data
    elif isinstance(data, list) and all(isinstance(v, int) and not isinstance(v, bool)
                                        for v in data):
        value.type, value.integer_array_value = 7, data
    elif isinstance(data, list) and all(isinstance(v, float) for v in data):
        value.type, value.double_array_value = 8, data
    elif isinstance(data, list) and all(isinstance(v, str) for v in data):
        value.type, value.string_array_value = 9, data
    elif isinstance(data, str):
        value.type, value.string_value = 4, data
    else:
        value.type, value.string_value = 4, text
    return value


def runs_in_daemon(_args: argparse.Namespace) -> bool:
    """One exchange with the node: the daemon may run it for the CLI (ros2cli.daemon.verb_host)."""
    return True


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rcl_interfaces.msg import Parameter
    from rcl_interfaces.srv import SetParameters
    from ros2cli.node.direct import cli_node
    from rosidl_runtime_py.set_message import INTEGER_RANGES
    value = parameter_value(args.value)
    low, high = INTEGER_RANGES['int64']
    if value.type == 2 and not low <= value.integer_value <= high:
        return f'Value {args.value} does not fit a 64-bit integer parameter [{low}, {high}]'
    target = find_node(args, context=context)
    if target is None:
        return 'Node not found'
    with cli_node(context, spin_time=args.spin_time) as node:
        request = SetParameters.Request(
            parameters=[Parameter(name=args.parameter_name, value=value)])
        response = call(node, SetParameters, f'{target}/set_parameters', request, context=context)
    print_result(
        response.results[0], 'Set parameter successful', 'Setting parameter failed', context=context
    )
    return 0
