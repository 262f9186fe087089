"""What the verbs of `ros2 param` share."""

from __future__ import annotations

import argparse
import time

from ros2cli.verb_context import VerbContext

TYPE_NAMES = {
    0: 'not set', 1: 'boolean', 2: 'integer', 3: 'double', 4: 'string', 5: 'byte array',
    6: 'boolean array', 7: 'integer array', 8: 'double array', 9: 'string array',
}


def add_timeout(parser: argparse.ArgumentParser) -> None:
    # ros2cli's default is 1 s; a node that has just started can take up to ~3 s to be
    # discovered on a loaded machine, so without --timeout the lookup waits up to 4 s.
    parser.add_argument('--timeout', metavar='N', type=int, default=None,
                        help='Wait for N seconds until node becomes available (default: up '
                        'to 4 sec while a new node is being discovered)')


def absolute(name: str | None) -> str | None:
    if not name:
        return None
    return name if name.startswith('/') else '/' + name


def find_node(args: argparse.Namespace, context: VerbContext) -> str | None:
    """The node's full name once the graph lists it, None when it does not appear in time."""
    from ros2cli.graph import graph_source
    target = absolute(args.node_name)
    timeout = getattr(args, 'timeout', None)
    hidden = args.include_hidden_nodes
    with graph_source(not args.no_daemon, args.spin_time, context) as source:
        graph = source.graph(ready=lambda g: target in g.node_names(hidden),
                             bound=None if timeout is None or args.no_daemon
                             else max(1.0, float(timeout)))
    return target if target in graph.node_names(hidden) else None


def call(node, srv_type, service: str, request, timeout: float = 5.0, *, context: VerbContext):
    """The node's answer; a node that is listed but never answers (not spinning, stuck in a
    callback) fails after `timeout` s instead of hanging the command as ros2cli does."""
    from ros2cli.node.direct import spin_once
    from ros2cli.verb_context import CliError
    client = node.create_client(srv_type, service)
    if not client.wait_for_service(timeout_sec=timeout):
        raise CliError(f"Service '{service}' not available: the node has no parameter services")
    future = client.call_async(request)
    deadline = time.monotonic() + timeout
    while not future.done():
        if time.monotonic() > deadline:
            client.remove_pending_request(future)
            raise CliError(f"Service '{service}' did not answer within {timeout:g} s: the node "
                           'is not spinning or is busy in a callback')
        spin_once(node, 0.1, context)
    if future.exception() is not None:
        raise CliError(f'Exception while calling service of node: {future.exception()}')
    return future.result()


def print_result(result, success: str, failure: str, context: VerbContext) -> None:
    """A SetParametersResult as ros2cli prints it: successes on stdout, failures on stderr."""
    reason = f': {result.reason}' if result.reason else ''
    if result.successful:
        print(success + reason, flush=True, file=context.stdout)
    else:
        print(failure + reason, file=context.stderr, flush=True)
