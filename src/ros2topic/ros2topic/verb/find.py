"""ros2 topic find: Output a list of available topics of a given type."""

from __future__ import annotations

import argparse

from ros2cli.names import print_names
from ros2cli.verb_context import VerbContext

from ros2topic.api import includes_hidden, query_graph
from ros2topic.verb import VerbExtension

HELP = 'Output a list of available topics of a given type'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_type', help="Name of the ROS topic type to filter for (e.g. "
                        "'std_msg/msg/String')")
    parser.add_argument('-c', '--count-topics', action='store_true',
                        help='Only display the number of topics discovered')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    print_names(
        [
            name
            for name, types in query_graph(args, context=context).topics(includes_hidden(args))
            if args.topic_type in types
        ],
        args.count_topics,
        context=context,
    )
    return 0


class FindVerb(VerbExtension):
    """Upstream's class of this verb, for code that drives it from Python."""
