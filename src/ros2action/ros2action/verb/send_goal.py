"""ros2 action send_goal: Send an action goal."""

from __future__ import annotations

import argparse
import sys
import time

from ros2cli.verb_context import CliError, VerbContext

HELP = 'Send an action goal'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('action_name', help="Name of the ROS action (e.g. '/fibonacci')")
    parser.add_argument('action_type',
                        help="Type of the ROS action (e.g. 'example_interfaces/action/Fibonacci')")
    group = parser.add_mutually_exclusive_group()
    group.add_argument('goal', nargs='?', default='{}',
                       help="Goal request values in YAML format (e.g. '{order: 10}')")
    group.add_argument('--stdin', action='store_true', help='Read goal from standard input')
    parser.add_argument('-f', '--feedback', action='store_true',
                        help='Echo feedback messages for the goal')
    parser.add_argument('--timeout', metavar='S', type=float, default=5.0,
                        help='Give up when no action server is available within S seconds '
                        '(default: %(default)s; 0 or less waits forever)')


# Longest wait for the cancel answer after Ctrl-C: the server may be gone by then.
CANCEL_TIMEOUT = 5.0


STATUS_NAMES = {0: 'UNKNOWN', 1: 'ACCEPTED', 2: 'EXECUTING', 3: 'CANCELING', 4: 'SUCCEEDED',
                5: 'CANCELED', 6: 'ABORTED'}


def runs_in_daemon(args: argparse.Namespace) -> bool:
    """One goal to its result (feedback streams as it comes), given on the command line (not
    --stdin): the daemon may run it for the CLI (ros2cli.daemon.verb_host)."""
    return not args.stdin


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rclpy.action import ActionClient
    from ros2cli.interface_types import import_type
    from ros2cli.message_yaml import populate
    from ros2cli.node.direct import cli_node
    try:
        action_type = import_type(args.action_type, 'action')
    except ValueError:
        raise CliError('The passed action type is invalid') from None
    if not all(hasattr(action_type, part) for part in ('Goal', 'Result', 'Feedback')):
        raise CliError('The passed type is not an action')
    text = sys.stdin.read() if args.stdin else args.goal
    # Checked before any node exists: a refused goal is never sent.
    goal = populate(action_type.Goal(), text)

    with cli_node(context, spin_time=args.spin_time) as node:
        client = ActionClient(node, action_type, args.action_name)
        try:
            return _run_goal(node, client, goal, args, context)
        finally:
            client.destroy()


def _run_goal(node, client, goal, args: argparse.Namespace, context: VerbContext
              ) -> int | str:
    from rosidl_runtime_py import message_to_yaml
    print('Waiting for an action server to become available...', flush=True, file=context.stdout)
    if not _wait_for_server(client, args.timeout, context):
        return (f"Action server '{args.action_name}' did not become available within "
                f'{args.timeout:g} s (is its node running? see `ros2 action list`)')
    print(f'Sending goal:\n     {message_to_yaml(goal)}', flush=True, file=context.stdout)

    # rclpy may hand over feedback before the goal response that accepts the goal (both can
    # arrive in one wait): hold it until 'Goal accepted' is printed, so the output keeps
    # ros2cli's order.
    early_feedback: list[str] | None = []

    def on_feedback(feedback) -> None:
        text = f'Feedback:\n    {message_to_yaml(feedback.feedback)}'
        if early_feedback is None:
            print(text, flush=True, file=context.stdout)
        else:
            early_feedback.append(text)

    handle = _wait(node, client.send_goal_async(
        goal, feedback_callback=on_feedback if args.feedback else None), 'sending goal', context)
    if not handle.accepted:
        print('Goal was rejected.', file=context.stdout)
        return 0
    print(
        f'Goal accepted with ID: {bytes(handle.goal_id.uuid).hex()}\n',
        flush=True,
        file=context.stdout,
    )
    for text in early_feedback:
        print(text, flush=True, file=context.stdout)
    early_feedback = None
    try:
        result = _wait(node, handle.get_result_async(), 'getting result', context)
    except KeyboardInterrupt:
        _cancel(node, handle, context)
        raise
    print(f'Result:\n    {message_to_yaml(result.result)}', file=context.stdout)
    print(
        f'Goal finished with status: {STATUS_NAMES.get(result.status, "UNKNOWN")}',
        file=context.stdout,
    )
    return 0


def _wait_for_server(client, timeout: float, context: VerbContext) -> bool:
    if timeout <= 0:
        while not client.wait_for_server(timeout_sec=1.0):
            context.check_cancelled()
        return True
    return client.wait_for_server(timeout_sec=timeout)


def _wait(node, future, what: str, context: VerbContext, timeout: float | None = None):
    """Spin until `future` is done; its result, or CliError naming what failed."""
    from ros2cli.node.direct import spin_once

    deadline = None if timeout is None else time.monotonic() + timeout
    while not future.done():
        if deadline is not None and time.monotonic() > deadline:
            raise CliError(f'Timed out {what}')
        spin_once(node, 0.1, context)
    if future.exception() is not None or future.result() is None:
        raise CliError(f'Exception while {what}: {future.exception()!r}')
    return future.result()


def _cancel(node, handle, context: VerbContext) -> None:
    """Ctrl-C while the goal runs: cancel it, as ros2cli does, before exiting."""
    from action_msgs.msg import GoalStatus

    if handle.status not in (
        GoalStatus.STATUS_ACCEPTED,
        GoalStatus.STATUS_EXECUTING,
        GoalStatus.STATUS_UNKNOWN,
    ):
        return
    print('Canceling goal...', flush=True, file=context.stdout)
    response = _wait(node, handle.cancel_goal_async(), 'canceling goal', context, CANCEL_TIMEOUT)
    canceling = list(response.goals_canceling)
    if len(canceling) != 1 or bytes(canceling[0].goal_id.uuid) != bytes(handle.goal_id.uuid):
        raise CliError('Failed to cancel goal')
    print('Goal canceled.', flush=True, file=context.stdout)
