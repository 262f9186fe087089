"""ros2 lifecycle set: Trigger lifecycle state transition."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2lifecycle.api import (
    absolute,
    add_node_name,
    call,
    exception_text,
    managed_node_names,
    transitions,
)

HELP = 'Trigger lifecycle state transition'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_node_name(parser)
    parser.add_argument('transition', help='The lifecycle transition')


def runs_in_daemon(_args: argparse.Namespace) -> bool:
    """A few service calls to the node: the daemon may run them for the CLI
    (ros2cli.daemon.verb_host)."""
    return True

def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from lifecycle_msgs.srv import ChangeState
    from ros2cli.node.direct import cli_node
    wanted = absolute(args.node_name)
    if wanted not in managed_node_names(args, args.include_hidden_nodes, wanted, context=context):
        return 'Node not found'
    with cli_node(context, spin_time=args.spin_time) as node:
        available = transitions(node, wanted, context=context)
        if isinstance(available, Exception):
            return exception_text(args.node_name, available)
        # By label first, then by id, as ros2lifecycle: '3' never shadows a label.
        chosen = next((t.transition for t in available if t.transition.label == args.transition),
                      None) or next((t.transition for t in available
                                     if str(t.transition.id) == args.transition), None)
        if chosen is None:
            # Asked nothing of the node: a transition it does not offer now changes nothing.
            return 'Unknown transition requested, available ones are:' + ''.join(
                f'\n- {t.transition.label} [{t.transition.id}]' for t in available)
        result = call(node, ChangeState, f'{wanted}/change_state',
                      ChangeState.Request(transition=chosen), context=context)
    if isinstance(result, Exception):
        print(exception_text(args.node_name, result), file=context.stderr)
    elif result.success:
        print('Transitioning successful', file=context.stdout)
    else:
        print('Transitioning failed', file=context.stderr)
    return 0
