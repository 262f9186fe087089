"""ros2 lifecycle get: Get lifecycle state for one or more nodes."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2lifecycle.api import (
    absolute,
    add_node_name,
    call,
    exception_text,
    managed_node_names,
)

HELP = 'Get lifecycle state for one or more nodes'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_node_name(parser, optional=True)


def runs_in_daemon(_args: argparse.Namespace) -> bool:
    """A few service calls to the node: the daemon may run them for the CLI
    (ros2cli.daemon.verb_host)."""
    return True

def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from lifecycle_msgs.srv import GetState
    from ros2cli.node.direct import cli_node
    wanted = absolute(args.node_name)
    names = managed_node_names(args, args.include_hidden_nodes, wanted, context=context)
    if wanted is not None and wanted not in names:
        return 'Node not found'
    with cli_node(context, spin_time=args.spin_time) as node:
        states = {
            name: call(node, GetState, f'{name}/get_state', GetState.Request(), context=context)
            for name in ([wanted] if wanted else names)
        }
    for name, state in sorted(states.items()):
        if isinstance(state, Exception):
            print(exception_text(name, state), file=context.stderr)
            if wanted:
                return 1
            continue
        prefix = '' if wanted else f'{name}: '
        print(
            f'{prefix}{state.current_state.label} [{state.current_state.id}]', file=context.stdout
        )
    return 0
