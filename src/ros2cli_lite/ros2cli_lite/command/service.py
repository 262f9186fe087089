"""ros2 service: list, type, find, info, call, echo."""

from __future__ import annotations

import argparse
import time

from ros2cli_lite.api import CliError, add_graph_verb, print_names

HIDDEN = '--include-hidden-services'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(HIDDEN, action='store_true', help='Consider hidden services as well')
    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        return add_graph_verb(verbs, name, func, help_text, HIDDEN,
                              'include_hidden_services_verb')

    p = verb('list', list_verb, 'Output a list of available services')
    p.add_argument('-t', '--show-types', action='store_true',
                   help='Additionally show the service type')
    p.add_argument('-c', '--count-services', action='store_true',
                   help='Only display the number of services discovered')
    p = verb('type', type_verb, 'Output a service\'s type')
    p.add_argument('service_name', help="Name of the ROS service to get type (e.g. '/talker')")
    p = verb('find', find_verb, 'Output a list of available services of a given type')
    p.add_argument('service_type', help="Name of the ROS service type to filter for "
                   "(e.g. 'rcl_interfaces/srv/ListParameters')")
    p.add_argument('-c', '--count-services', action='store_true',
                   help='Only display the number of services discovered')
    p = verb('info', info_verb, 'Print information about a service')
    p.add_argument('service_name', help="Name of the ROS service to get info (e.g. "
                   "'/add_two_ints')")
    p = verb('call', call_verb, 'Call a service')
    p.add_argument('service_name', help="Name of the ROS service to call to (e.g. "
                   "'/add_two_ints')")
    p.add_argument('service_type', help="Type of the ROS service (e.g. 'std_srvs/srv/Empty')")
    group = p.add_mutually_exclusive_group()
    group.add_argument('values', nargs='?', default='{}',
                       help="Values to fill the service request with in YAML format (e.g. "
                       "'{a: 1, b: 2}'), otherwise the service request is sent with default "
                       'values')
    group.add_argument('--stdin', action='store_true', help='Read values from standard input')
    p.add_argument('-r', '--rate', metavar='N', type=float,
                   help='Repeat the call at a specific rate in Hz')
    p.add_argument('--timeout', metavar='S', type=float, default=5.0,
                   help='Give up when the service is not available within S seconds '
                   '(default: %(default)s; 0 or less waits forever)')
    p = verb('echo', echo_verb, 'Echo a service')
    p.add_argument('service_name', help="Name of the ROS service to echo (e.g. "
                   "'/add_two_ints')")
    p.add_argument('service_type', nargs='?', help="Type of the ROS service (e.g. "
                   "'example_interfaces/srv/AddTwoInts')")
    p.add_argument('--flow-style', action='store_true',
                   help='Print collections in the block style (not available with csv format)')


def _include_hidden(args: argparse.Namespace) -> bool:
    return bool(args.include_hidden_services or args.include_hidden_services_verb)


def _graph(args: argparse.Namespace, ready=None):
    from ros2cli_lite.graph import graph_source
    with graph_source(not args.no_daemon) as source:
        return source.graph(ready=ready)


def list_verb(args: argparse.Namespace) -> int:
    found = _graph(args).services(_include_hidden(args))
    if args.count_services:
        print(len(found))
        return 0
    for name, types in found:
        print(f'{name} [{", ".join(types)}]' if args.show_types else name)
    return 0


def _lookup(args: argparse.Namespace):
    """(types or None, graph) of the named service, waiting a little for it to appear."""
    hidden = _include_hidden(args)
    graph = _graph(args, ready=lambda g: args.service_name in dict(g.services(hidden)))
    return dict(graph.services(hidden)).get(args.service_name), graph


def type_verb(args: argparse.Namespace) -> int:
    found, _ = _lookup(args)
    if found is None:
        return 1
    for service_type in found:
        print(service_type)
    return 0


def find_verb(args: argparse.Namespace) -> int:
    print_names([name for name, types in _graph(args).services(_include_hidden(args))
                 if args.service_type in types], args.count_services)
    return 0


def info_verb(args: argparse.Namespace) -> int | str:
    found, graph = _lookup(args)
    if found is None:
        return f"Unknown service '{args.service_name}'"
    servers, clients = graph.service_counts(args.service_name)
    print(f'Type: {found[0] if len(found) == 1 else found}')
    print(f'Clients count: {clients}')
    print(f'Services count: {servers}')
    return 0


def call_verb(args: argparse.Namespace) -> int | str:
    import sys

    from ros2cli_lite.api import cli_node, import_type, populate, spin_once
    if args.rate is not None and args.rate <= 0:
        raise CliError('rate must be greater than zero')
    period = 1.0 / args.rate if args.rate else None
    try:
        srv_type = import_type(args.service_type, 'srv')
    except ValueError:
        raise CliError('The passed service type is invalid') from None
    if not hasattr(srv_type, 'Request') or not hasattr(srv_type, 'Response'):
        raise CliError('The passed type is not a service')
    values = sys.stdin.read() if args.stdin else args.values
    # Everything is checked before a node exists: a refused request is never sent.
    request = populate(srv_type.Request(), values)

    started = time.monotonic()
    with cli_node() as node:
        client = node.create_client(srv_type, args.service_name)
        if not _wait_for_service(client, started, args.timeout):
            return (f"Service '{args.service_name}' did not become available within "
                    f'{args.timeout:g} s (is its node running? see `ros2 service list`)')
        while True:
            print(f'requester: making request: {request!r}\n', flush=True)
            last_call = time.monotonic()
            future = client.call_async(request)
            while not future.done():
                spin_once(node, 0.1)
            if future.exception() is not None:
                raise CliError(f'Exception while calling service: {future.exception()!r}')
            print(f'response:\n{future.result()!r}\n', flush=True)
            if period is None:
                break
            remaining = last_call + period - time.monotonic()
            if remaining > 0:
                time.sleep(remaining)
    return 0


def _wait_for_service(client, started: float, timeout: float) -> bool:
    """Quietly give discovery three seconds, then say that we wait (as ros2cli does), bounded."""
    forever = timeout <= 0
    grace = started + (3.0 if forever else min(3.0, timeout))
    if client.wait_for_service(timeout_sec=max(0.0, grace - time.monotonic())):
        return True
    print('waiting for service to become available...', flush=True)
    if forever:
        while not client.wait_for_service(timeout_sec=1.0):
            pass
        return True
    return client.wait_for_service(timeout_sec=max(0.0, started + timeout - time.monotonic()))


EVENT_TYPES = {0: 'REQUEST_SENT', 1: 'REQUEST_RECEIVED', 2: 'RESPONSE_SENT',
               3: 'RESPONSE_RECEIVED'}
# How long echo lets discovery find the event publishers before saying there are none.
ECHO_DISCOVERY = 2.0


def echo_verb(args: argparse.Namespace) -> int | str:
    from rclpy.qos import qos_profile_services_default

    from ros2cli_lite.api import cli_node, import_type, message_to_ordered, spin_once, to_yaml
    type_name = args.service_type
    if type_name is None:
        found, _ = _lookup(args)
        if found is None:
            raise CliError(f"Could not load the type for the passed service: no service "
                           f"'{args.service_name}' in the graph (see `ros2 service list`)")
        type_name = found[0]
    try:
        srv_type = import_type(type_name, 'srv')
    except ValueError:
        raise CliError(f"The service type '{type_name}' is invalid") from None
    if not hasattr(srv_type, 'Event'):
        raise CliError(f"'{type_name}' is not a service type")
    with cli_node() as node:
        topic = args.service_name.rstrip('/') + '/_service_event'

        def on_event(event) -> None:
            data = message_to_ordered(event)
            data['info']['event_type'] = EVENT_TYPES.get(data['info']['event_type'],
                                                         data['info']['event_type'])
            print(to_yaml(data, args.flow_style) + '---', flush=True)

        subscription = node.create_subscription(srv_type.Event, topic, on_event,
                                                qos_profile_services_default)
        deadline = time.monotonic() + ECHO_DISCOVERY
        while subscription.get_publisher_count() < 1 and time.monotonic() < deadline:
            spin_once(node, 0.05)
        if subscription.get_publisher_count() < 1:
            print(f"No publishers on topic '{topic}'; is service introspection on the client "
                  'or server enabled?', flush=True)
        while True:
            spin_once(node, 0.5)

