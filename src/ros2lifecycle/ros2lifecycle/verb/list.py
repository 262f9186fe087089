"""ros2 lifecycle list: Output a list of available transitions."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2lifecycle.api import (
    absolute,
    add_node_name,
    exception_text,
    managed_node_names,
    transitions,
)

HELP = 'Output a list of available transitions'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_node_name(parser)
    parser.add_argument('-a', '--all', action='store_true',
                        help='Display all existing transitions')


def runs_in_daemon(_args: argparse.Namespace) -> bool:
    """A few service calls to the node: the daemon may run them for the CLI
    (ros2cli.daemon.verb_host)."""
    return True

def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from ros2cli.node.direct import cli_node
    wanted = absolute(args.node_name)
    if wanted not in managed_node_names(args, args.include_hidden_nodes, wanted, context=context):
        return 'Node not found'
    with cli_node(context, spin_time=args.spin_time) as node:
        found = transitions(node, wanted, graph=args.all, context=context)
    if isinstance(found, Exception):
        return exception_text(args.node_name, found)
    for item in found:
        print(f'- {item.transition.label} [{item.transition.id}]\n'
              f'\tStart: {item.start_state.label}\n'
              f'\tGoal: {item.goal_state.label}', file=context.stdout)
    return 0
