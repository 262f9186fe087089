"""ros2 service: list, type, find, info, call, echo."""

from __future__ import annotations

import argparse
import time

from ros2cli_lite.api import CliError, add_graph_verb, is_hidden

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


def services(node, include_hidden: bool) -> list[tuple[str, list[str]]]:
    return [(name, types) for name, types in node.get_service_names_and_types()
            if include_hidden or not is_hidden(name)]


def list_verb(args: argparse.Namespace) -> int:
    from ros2cli_lite.api import cli_node, wait_for_graph
    with cli_node() as node:
        wait_for_graph(node)
        found = services(node, _include_hidden(args))
    if args.count_services:
        print(len(found))
        return 0
    for name, types in found:
        print(f'{name} [{", ".join(types)}]' if args.show_types else name)
    return 0


def _lookup(args: argparse.Namespace) -> list[str] | None:
    from ros2cli_lite.api import cli_node
    with cli_node() as node:
        return _lookup_in(node, args.service_name, _include_hidden(args))


def type_verb(args: argparse.Namespace) -> int:
    found = _lookup(args)
    if found is None:
        return 1
    for service_type in found:
        print(service_type)
    return 0


def find_verb(args: argparse.Namespace) -> int:
    from ros2cli_lite.api import cli_node, print_names, wait_for_graph
    with cli_node() as node:
        wait_for_graph(node)
        names = [name for name, types in services(node, _include_hidden(args))
                 if args.service_type in types]
    print_names(names, args.count_services)
    return 0


def info_verb(args: argparse.Namespace) -> int | str:
    from ros2cli_lite.api import cli_node, wait_for_graph
    hidden = _include_hidden(args)
    with cli_node() as node:
        def types():
            return dict(services(node, hidden)).get(args.service_name)
        wait_for_graph(node, ready=lambda: types() is not None)
        found = types()
        if found is None:
            return f"Unknown service '{args.service_name}'"
        print(f'Type: {found[0] if len(found) == 1 else found}')
        print(f'Clients count: {node.count_clients(args.service_name)}')
        print(f'Services count: {node.count_services(args.service_name)}')
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
    if args.service_type is not None:
        try:
            srv_type = import_type(args.service_type, 'srv')
        except ValueError:
            raise CliError(f"The service type '{args.service_type}' is invalid") from None
    with cli_node() as node:
        if args.service_type is None:
            found = _lookup_in(node, args.service_name)
            if found is None:
                raise CliError(f"Could not load the type for the passed service: no service "
                               f"'{args.service_name}' in the graph (see `ros2 service list`)")
            try:
                srv_type = import_type(found[0], 'srv')
            except ValueError:
                raise CliError(f"The service type '{found[0]}' is invalid") from None
        if not hasattr(srv_type, 'Event'):
            raise CliError(f"'{args.service_type}' is not a service type")
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


def _lookup_in(node, name: str, include_hidden: bool = True) -> list[str] | None:
    """The types of service `name`, once discovered (None if it never shows up)."""
    from ros2cli_lite.api import wait_for_graph

    def types():
        return dict(services(node, include_hidden)).get(name)
    wait_for_graph(node, ready=lambda: types() is not None, settle=0.2)
    return types()
