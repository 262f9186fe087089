"""ros2 param dump: Show all of the parameters of a node in a YAML file format."""

from __future__ import annotations

import argparse
import os

from ros2cli.verb_context import VerbContext

from ros2param.api import add_timeout, call, find_node

HELP = 'Show all of the parameters of a node in a YAML file format'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('node_name', help='Name of the ROS node')
    parser.add_argument('--output-dir', metavar='DIR', default=None,
                        help='Write the YAML to DIR/<node name>.yaml instead of standard output '
                        '(Humble\'s option; Jazzy removed it)')
    add_timeout(parser)


def _insert(tree: dict, name: str, value) -> None:
    """Nest a dotted parameter name as ros2cli's dump does: 'a.b.c' -> {a: {b: {c: value}}}."""
    head, dot, rest = name.partition('.')
    if dot:
        _insert(tree.setdefault(head, {}), rest, value)
    else:
        tree[name] = value


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    import yaml
    from rcl_interfaces.srv import GetParameters, ListParameters
    from rclpy.parameter import parameter_value_to_python
    from ros2cli.node.direct import cli_node
    if args.output_dir is not None and not os.path.isdir(args.output_dir):
        return f"Output directory '{args.output_dir}' does not exist"
    target = find_node(args, context=context)
    if target is None:
        return 'Node not found'
    with cli_node(context, spin_time=args.spin_time) as node:
        listed = call(node, ListParameters, f'{target}/list_parameters',
                       ListParameters.Request(), context=context)
        names = sorted(listed.result.names)
        got = call(node, GetParameters, f'{target}/get_parameters',
                    GetParameters.Request(names=names), context=context)
    parameters: dict = {}
    for name, value in zip(names, got.values, strict=False):
        _insert(parameters, name, parameter_value_to_python(value))
    text = yaml.dump({target: {'ros__parameters': parameters}}, default_flow_style=False)
    if args.output_dir is None:
        print(text, file=context.stdout)
        return 0
    path = os.path.join(args.output_dir, target.lstrip('/').replace('/', '__') + '.yaml')
    print(f'Saving to:  {path}', file=context.stdout)
    with open(path, 'w', encoding='utf-8') as output:
        output.write(text)
    return 0
