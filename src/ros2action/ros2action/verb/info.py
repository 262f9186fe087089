"""ros2 action info: Print information about an action."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2action.api import absolute, query_graph

HELP = 'Print information about an action'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('action_name',
                        help="Name of the ROS action to get info (e.g. '/fibonacci')")
    parser.add_argument('-t', '--show-types', action='store_true',
                        help='Additionally show the action type')
    parser.add_argument('-c', '--count', action='store_true',
                        help='Only display the number of action clients and action servers')


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rclpy.exceptions import InvalidTopicNameException
    from rclpy.validate_full_topic_name import validate_full_topic_name

    action = absolute(args.action_name)
    try:
        validate_full_topic_name(action)
    except InvalidTopicNameException as error:
        # rclpy's text: 'Invalid topic name: <why>:' then the name with a caret under it.
        why = str(error).splitlines()[0].removeprefix('Invalid topic name: ').rstrip(':')
        return f"Invalid action name '{args.action_name}': {why}"
    servers, clients = query_graph(
        args, detail=True, action=action, context=context
    ).action_endpoints(action)
    print(f'Action: {action}', file=context.stdout)
    for title, entries in (('Action clients', clients), ('Action servers', servers)):
        print(f'{title}: {len(entries)}', file=context.stdout)
        if args.count:
            continue
        for name, types in entries:
            print(
                f'    {name} [{", ".join(types)}]' if args.show_types else f'    {name}',
                file=context.stdout,
            )
    return 0
