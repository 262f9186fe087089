"""What the verbs of `ros2 service` share."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

HIDDEN = '--include-hidden-services'


def includes_hidden(args: argparse.Namespace) -> bool:
    return bool(args.include_hidden_services or args.include_hidden_services_verb)


def query_graph(args: argparse.Namespace, ready=None, *, context: VerbContext):
    from ros2cli.graph import graph_source
    with graph_source(not args.no_daemon, args.spin_time, context) as source:
        return source.graph(ready=ready)


def lookup(args: argparse.Namespace, context: VerbContext):
    """(types or None, graph) of the named service, waiting a little for it to appear."""
    hidden = includes_hidden(args)
    graph = query_graph(
        args, ready=lambda g: args.service_name in dict(g.services(hidden)), context=context
    )
    return dict(graph.services(hidden)).get(args.service_name), graph
