"""ros2 param load: Load parameter file for a node."""

from __future__ import annotations

import argparse
import os

from ros2cli.verb_context import VerbContext

from ros2param.api import add_timeout, call, find_node, print_result

HELP = 'Load parameter file for a node'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('node_name', help='Name of the ROS node')
    parser.add_argument('parameter_file', help='Parameter file')
    parser.add_argument('--no-use-wildcard', action='store_true',
                        help="Do not load parameters in the '/**' namespace into the node")
    add_timeout(parser)


def _read_parameter_file(path: str, use_wildcard: bool) -> list:
    """The rcl_interfaces Parameters of a params file, in file order; CliError if unusable."""
    import yaml
    from rclpy.parameter import parameter_dict_from_yaml_file
    from ros2cli.message_yaml import yaml_problem
    from ros2cli.verb_context import CliError
    if not os.path.isfile(path):
        # The OS's words, as upstream's (its open() error): 'No such file or directory'.
        raise CliError(f"Parameter file '{path}': No such file or directory")
    try:
        return list(parameter_dict_from_yaml_file(path, use_wildcard).values())
    except yaml.YAMLError as error:
        raise CliError(f"Parameter file '{path}' is not valid YAML: "
                       f'{yaml_problem(error)}') from None
    except (RuntimeError, AttributeError, TypeError, ValueError) as error:
        raise CliError(f"Parameter file '{path}' is not a ROS parameter file "
                       "(expected '<node>: {ros__parameters: {name: value}}'): "
                       f'{error}') from None


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rcl_interfaces.srv import SetParameters
    from ros2cli.node.direct import cli_node
    # The node first, then the file, as upstream: an unknown node is 'Node not found'.
    target = find_node(args, context=context)
    if target is None:
        return 'Node not found'
    parameters = _read_parameter_file(args.parameter_file, not args.no_use_wildcard)
    with cli_node(context, spin_time=args.spin_time) as node:
        response = call(node, SetParameters, f'{target}/set_parameters',
                         SetParameters.Request(parameters=parameters), context=context)
    for parameter, result in zip(parameters, response.results, strict=False):
        print_result(result, f'Set parameter {parameter.name} successful',
                      f'Set parameter {parameter.name} failed', context=context)
    return 0
