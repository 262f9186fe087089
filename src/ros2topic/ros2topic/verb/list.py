"""ros2 topic list: Output a list of available topics."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2topic.api import includes_hidden, query_graph
from ros2topic.verb import VerbExtension

HELP = 'Output a list of available topics'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-t', '--show-types', action='store_true',
                        help='Additionally show the topic type')
    parser.add_argument('-c', '--count-topics', action='store_true',
                        help='Only display the number of topics discovered')
    parser.add_argument('-v', '--verbose', action='store_true',
                        help='List full details about each topic')


def _plural(count: int, word: str) -> str:
    return f'{count} {word}{"s" if count > 1 else ""}'


def main(args: argparse.Namespace, context: VerbContext) -> int:
    graph = query_graph(args, context=context)
    found = graph.topics(includes_hidden(args))
    if args.count_topics:
        print(len(found), file=context.stdout)
    elif args.verbose:
        for title, index, word in (('Published topics:', 0, 'publisher'),
                                   ('Subscribed topics:', 1, 'subscriber')):
            print(title, file=context.stdout)
            for name, types in found:
                n = graph.topic_counts(name)[index]
                if n:
                    print(f' * {name} [{", ".join(types)}] {_plural(n, word)}', file=context.stdout)
            print(file=context.stdout)
    else:
        for name, types in found:
            print(f'{name} [{", ".join(types)}]' if args.show_types else name, file=context.stdout)
    return 0


class ListVerb(VerbExtension):
    """Upstream's class of this verb, for code that drives it from Python."""
