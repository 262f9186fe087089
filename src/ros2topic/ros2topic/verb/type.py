"""ros2 topic type: Print a topic's type."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2topic.api import includes_hidden, query_graph
from ros2topic.verb import VerbExtension

HELP = "Print a topic's type"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_name', help="Name of the ROS topic to get type (e.g. '/chatter')")


def main(args: argparse.Namespace, context: VerbContext) -> int:
    hidden = includes_hidden(args)
    graph = query_graph(
        args, ready=lambda g: args.topic_name in dict(g.topics(hidden)), context=context
    )
    found = dict(graph.topics(hidden)).get(args.topic_name)
    if found is None:
        return 1
    for topic_type in found:
        print(topic_type, file=context.stdout)
    return 0


class TypeVerb(VerbExtension):
    """Upstream's class of this verb, for code that drives it from Python."""
