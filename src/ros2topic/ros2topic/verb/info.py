"""ros2 topic info: Print information about a topic."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2topic.verb import VerbExtension

HELP = 'Print information about a topic'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_name', help="Name of the ROS topic to get info (e.g. '/chatter')")
    parser.add_argument('-v', '--verbose', action='store_true',
                        help='Prints detailed information like the node name, node namespace, '
                        'topic type, GUID and QoS Profile of the publishers and subscribers to '
                        'this topic')


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from ros2cli.graph import graph_source
    end = '\n\n' if args.verbose else '\n'
    with graph_source(not args.no_daemon, args.spin_time, context) as source:
        graph = source.graph(ready=lambda g: args.topic_name in dict(g.topics(True)))
        found = dict(graph.topics(True)).get(args.topic_name)
        if found is None:
            return f"Unknown topic '{args.topic_name}'"
        publishers, subscribers = source.endpoints(args.topic_name) if args.verbose else ([], [])
    publisher_count, subscriber_count = graph.topic_counts(args.topic_name)
    print(f'Type: {found[0] if len(found) == 1 else found}', end=end, file=context.stdout)
    print(f'Publisher count: {publisher_count}', end=end, file=context.stdout)
    for text in publishers:
        print(text, end=end, file=context.stdout)
    print(f'Subscription count: {subscriber_count}', end=end, file=context.stdout)
    for text in subscribers:
        print(text, end=end, file=context.stdout)
    return 0


class InfoVerb(VerbExtension):
    """Upstream's class of this verb, for code that drives it from Python."""
