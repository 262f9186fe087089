"""ros2 param: list, get, set, describe, dump, load, delete (through the node's rcl_interfaces
services)."""

from __future__ import annotations

import argparse
import os
import sys

from ros2cli_lite.api import add_graph_verb

TYPE_NAMES = {
    0: 'not set', 1: 'boolean', 2: 'integer', 3: 'double', 4: 'string', 5: 'byte array',
    6: 'boolean array', 7: 'integer array', 8: 'double array', 9: 'string array',
}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        parser = add_graph_verb(verbs, name, func, help_text)
        parser.add_argument('--include-hidden-nodes', action='store_true',
                            help='Consider hidden nodes as well')
        return parser

    p = verb('list', list_verb, 'Output a list of available parameters')
    p.add_argument('node_name', nargs='?', help='Name of the ROS node')
    p.add_argument('--param-prefixes', nargs='+', default=[],
                   help='Only list parameters with the provided prefixes')
    p.add_argument('--param-type', action='store_true',
                   help='Print parameter types with parameter names')
    p = verb('get', get_verb, 'Get parameter')
    p.add_argument('node_name', help='Name of the ROS node')
    p.add_argument('parameter_name', help='Name of the parameter')
    p.add_argument('--hide-type', action='store_true', help='Hide the type information')
    p = verb('set', set_verb, 'Set parameter')
    p.add_argument('node_name', help='Name of the ROS node')
    p.add_argument('parameter_name', help='Name of the parameter')
    p.add_argument('value', help='Value of the parameter')
    _add_timeout(p)
    p = verb('describe', describe_verb, 'Show descriptive information about declared parameters')
    p.add_argument('node_name', help='Name of the ROS node')
    p.add_argument('parameter_names', nargs='+', help='Names of the parameters')
    p = verb('dump', dump_verb, 'Show all of the parameters of a node in a YAML file format')
    p.add_argument('node_name', help='Name of the ROS node')
    p.add_argument('--output-dir', metavar='DIR', default=None,
                   help='Write the YAML to DIR/<node name>.yaml instead of standard output '
                   '(Humble\'s option; Jazzy removed it)')
    _add_timeout(p)
    p = verb('load', load_verb, 'Load parameter file for a node')
    p.add_argument('node_name', help='Name of the ROS node')
    p.add_argument('parameter_file', help='Parameter file')
    p.add_argument('--no-use-wildcard', action='store_true',
                   help="Do not load parameters in the '/**' namespace into the node")
    _add_timeout(p)
    p = verb('delete', delete_verb, 'Delete parameter')
    p.add_argument('node_name', help='Name of the ROS node')
    p.add_argument('parameter_name', help='Name of the parameter')
    _add_timeout(p)


def _add_timeout(parser: argparse.ArgumentParser) -> None:
    # ros2cli's default is 1 s; a node that has just started can take up to ~3 s to be
    # discovered on a loaded machine, so without --timeout the lookup waits up to 4 s.
    parser.add_argument('--timeout', metavar='N', type=int, default=None,
                        help='Wait for N seconds until node becomes available (default: up '
                        'to 4 sec while a new node is being discovered)')


def absolute(name: str | None) -> str | None:
    if not name:
        return None
    return name if name.startswith('/') else '/' + name


def _find_node(args: argparse.Namespace) -> str | None:
    """The node's full name once the graph lists it, None when it does not appear in time."""
    from ros2cli_lite.graph import graph_source
    target = absolute(args.node_name)
    timeout = getattr(args, 'timeout', None)
    hidden = args.include_hidden_nodes
    with graph_source(not args.no_daemon) as source:
        graph = source.graph(ready=lambda g: target in g.node_names(hidden),
                             bound=None if timeout is None or args.no_daemon
                             else max(1.0, float(timeout)))
    return target if target in graph.node_names(hidden) else None


def _call(node, srv_type, service: str, request, timeout: float = 5.0):
    from ros2cli_lite.api import CliError, spin_once
    client = node.create_client(srv_type, service)
    if not client.wait_for_service(timeout_sec=timeout):
        raise CliError(f"Service '{service}' not available: the node has no parameter services")
    future = client.call_async(request)
    while not future.done():
        spin_once(node, 0.1)
    if future.exception() is not None:
        raise CliError(f'Exception while calling service of node: {future.exception()}')
    return future.result()


def list_verb(args: argparse.Namespace) -> int | str:
    from ros2cli_lite.graph import graph_source
    if args.node_name:
        target = _find_node(args)
        if target is None:
            return 'Node not found'
        targets = [target]
        # The node may be listed before its parameter services have been discovered.
        with graph_source(not args.no_daemon) as source:
            source.graph(ready=lambda g: f'{target}/list_parameters' in dict(g.services(True)))
    else:
        with graph_source(not args.no_daemon) as source:
            graph = source.graph()
        services = dict(graph.services(True))
        targets = [name for name in graph.node_names(args.include_hidden_nodes)
                   if f'{name}/list_parameters' in services]
    if targets:
        _list_parameters(args, sorted(set(targets)))
    return 0


def _list_parameters(args: argparse.Namespace, targets: list[str]) -> None:
    """Ask each node for its parameters directly (the daemon never calls a node)."""
    from rcl_interfaces.srv import DescribeParameters, ListParameters

    from ros2cli_lite.api import cli_node
    with cli_node() as node:
        for target in targets:
            request = ListParameters.Request()
            request.prefixes = list(args.param_prefixes)
            response = _call(node, ListParameters, f'{target}/list_parameters', request)
            names = sorted(response.result.names)
            if not args.node_name:
                print(f'{target}:')
            types = {}
            if args.param_type:
                described = _call(node, DescribeParameters, f'{target}/describe_parameters',
                                  DescribeParameters.Request(names=names))
                types = {d.name: TYPE_NAMES.get(d.type, 'unknown type')
                         for d in described.descriptors}
            for name in names:
                print(f'  {name} (type: {types[name]})' if args.param_type else f'  {name}')


LABELS = {
    1: ('Boolean value is:', 'bool_value'), 2: ('Integer value is:', 'integer_value'),
    3: ('Double value is:', 'double_value'), 4: ('String value is:', 'string_value'),
    5: ('Byte values are:', 'byte_array_value'), 6: ('Boolean values are:', 'bool_array_value'),
    7: ('Integer values are:', 'integer_array_value'),
    8: ('Double values are:', 'double_array_value'),
    9: ('String values are:', 'string_array_value'),
}


def get_verb(args: argparse.Namespace) -> int | str:
    from rcl_interfaces.srv import GetParameters

    from ros2cli_lite.api import cli_node
    target = _find_node(args)
    if target is None:
        return 'Node not found'
    with cli_node() as node:
        response = _call(node, GetParameters, f'{target}/get_parameters',
                         GetParameters.Request(names=[args.parameter_name]))
    if not response.values:
        return 'Parameter not set'
    value = response.values[0]
    if value.type == 0:
        print('Parameter not set.' if not args.hide_type else None)
        return 0
    if value.type not in LABELS:
        return f"Unknown parameter type '{value.type}'"
    label, attribute = LABELS[value.type]
    data = getattr(value, attribute)
    if value.type >= 5:
        data = list(data) if value.type != 5 else [bytes([b]) if isinstance(b, int) else b
                                                   for b in data]
    print(data if args.hide_type else f'{label} {data}')
    return 0


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


def set_verb(args: argparse.Namespace) -> int | str:
    from rcl_interfaces.msg import Parameter
    from rcl_interfaces.srv import SetParameters

    from ros2cli_lite.api import INTEGER_RANGES, cli_node
    value = parameter_value(args.value)
    low, high = INTEGER_RANGES['int64']
    if value.type == 2 and not low <= value.integer_value <= high:
        return f'Value {args.value} does not fit a 64-bit integer parameter [{low}, {high}]'
    target = _find_node(args)
    if target is None:
        return 'Node not found'
    with cli_node() as node:
        request = SetParameters.Request(
            parameters=[Parameter(name=args.parameter_name, value=value)])
        response = _call(node, SetParameters, f'{target}/set_parameters', request)
    _print_result(response.results[0], 'Set parameter successful', 'Setting parameter failed')
    return 0


def _print_result(result, success: str, failure: str) -> None:
    """A SetParametersResult as ros2cli prints it: successes on stdout, failures on stderr."""
    reason = f': {result.reason}' if result.reason else ''
    if result.successful:
        print(success + reason, flush=True)
    else:
        print(failure + reason, file=sys.stderr, flush=True)


def describe_verb(args: argparse.Namespace) -> int | str:
    from rcl_interfaces.srv import DescribeParameters

    from ros2cli_lite.api import cli_node
    target = _find_node(args)
    if target is None:
        return 'Node not found'
    with cli_node() as node:
        response = _call(node, DescribeParameters, f'{target}/describe_parameters',
                         DescribeParameters.Request(names=args.parameter_names))
    for descriptor in response.descriptors:
        print('Parameter name:', descriptor.name)
        print('  Type:', TYPE_NAMES.get(descriptor.type, 'unknown type'))
        if descriptor.description:
            print('  Description:', descriptor.description)
        ranges = list(descriptor.floating_point_range) + list(descriptor.integer_range)
        if (descriptor.read_only or ranges or descriptor.additional_constraints):
            print('  Constraints:')
            if descriptor.read_only:
                print('    Read only: true')
            if ranges:
                print('    Min value:', ranges[0].from_value)
                print('    Max value:', ranges[0].to_value)
                if ranges[0].step:
                    print('    Step:', ranges[0].step)
            if descriptor.additional_constraints:
                print('    Additional constraints:', descriptor.additional_constraints)
    return 0


def _insert(tree: dict, name: str, value) -> None:
    """Nest a dotted parameter name as ros2cli's dump does: 'a.b.c' -> {a: {b: {c: value}}}."""
    head, dot, rest = name.partition('.')
    if dot:
        _insert(tree.setdefault(head, {}), rest, value)
    else:
        tree[name] = value


def dump_verb(args: argparse.Namespace) -> int | str:
    import yaml
    from rcl_interfaces.srv import GetParameters, ListParameters
    from rclpy.parameter import parameter_value_to_python

    from ros2cli_lite.api import cli_node
    if args.output_dir is not None and not os.path.isdir(args.output_dir):
        return f"Output directory '{args.output_dir}' does not exist"
    target = _find_node(args)
    if target is None:
        return 'Node not found'
    with cli_node() as node:
        listed = _call(node, ListParameters, f'{target}/list_parameters',
                       ListParameters.Request())
        names = sorted(listed.result.names)
        got = _call(node, GetParameters, f'{target}/get_parameters',
                    GetParameters.Request(names=names))
    parameters: dict = {}
    for name, value in zip(names, got.values, strict=False):
        _insert(parameters, name, parameter_value_to_python(value))
    text = yaml.dump({target: {'ros__parameters': parameters}}, default_flow_style=False)
    if args.output_dir is None:
        print(text)
        return 0
    path = os.path.join(args.output_dir, target.lstrip('/').replace('/', '__') + '.yaml')
    print(f'Saving to:  {path}')
    with open(path, 'w', encoding='utf-8') as output:
        output.write(text)
    return 0


def _read_parameter_file(path: str, use_wildcard: bool) -> list:
    """The rcl_interfaces Parameters of a params file, in file order; CliError if unusable."""
    import yaml
    from rclpy.parameter import parameter_dict_from_yaml_file

    from ros2cli_lite.api import CliError, yaml_problem
    if not os.path.isfile(path):
        raise CliError(f"Parameter file '{path}' does not exist")
    try:
        return list(parameter_dict_from_yaml_file(path, use_wildcard).values())
    except yaml.YAMLError as error:
        raise CliError(f"Parameter file '{path}' is not valid YAML: "
                       f'{yaml_problem(error)}') from None
    except (RuntimeError, AttributeError, TypeError, ValueError) as error:
        raise CliError(f"Parameter file '{path}' is not a ROS parameter file "
                       "(expected '<node>: {ros__parameters: {name: value}}'): "
                       f'{error}') from None


def load_verb(args: argparse.Namespace) -> int | str:
    from rcl_interfaces.srv import SetParameters

    from ros2cli_lite.api import cli_node
    parameters = _read_parameter_file(args.parameter_file, not args.no_use_wildcard)
    target = _find_node(args)
    if target is None:
        return 'Node not found'
    with cli_node() as node:
        response = _call(node, SetParameters, f'{target}/set_parameters',
                         SetParameters.Request(parameters=parameters))
    for parameter, result in zip(parameters, response.results, strict=False):
        _print_result(result, f'Set parameter {parameter.name} successful',
                      f'Set parameter {parameter.name} failed')
    return 0


def delete_verb(args: argparse.Namespace) -> int | str:
    from rcl_interfaces.msg import Parameter, ParameterValue
    from rcl_interfaces.srv import SetParameters

    from ros2cli_lite.api import cli_node
    target = _find_node(args)
    if target is None:
        return 'Node not found'
    with cli_node() as node:
        request = SetParameters.Request(
            parameters=[Parameter(name=args.parameter_name, value=ParameterValue())])
        response = _call(node, SetParameters, f'{target}/set_parameters', request)
    _print_result(response.results[0], 'Deleted parameter successfully',
                  'Deleting parameter failed')
    return 0
