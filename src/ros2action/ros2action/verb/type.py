"""ros2 action type: Print a action's type."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2action.api import absolute, query_graph

HELP = "Print a action's type"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('action_name',
                        help="Name of the ROS action to get info (e.g. '/fibonacci')")


def main(args: argparse.Namespace, context: VerbContext) -> int:
    action = absolute(args.action_name)
    found = dict(query_graph(args, action=action, context=context).actions()).get(action)
    if found is None:
        return 1
    for action_type in found:
        print(action_type, file=context.stdout)
    return 0
