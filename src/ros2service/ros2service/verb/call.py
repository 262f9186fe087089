"""ros2 service call: Call a service."""

from __future__ import annotations

import argparse
import time

from ros2cli.verb_context import CliError, VerbContext

HELP = 'Call a service'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('service_name', help="Name of the ROS service to call to (e.g. "
                        "'/add_two_ints')")
    parser.add_argument('service_type', help="Type of the ROS service (e.g. 'std_srvs/srv/Empty')")
    group = parser.add_mutually_exclusive_group()
    group.add_argument('values', nargs='?', default='{}',
                       help="Values to fill the service request with in YAML format (e.g. "
                       "'{a: 1, b: 2}'), otherwise the service request is sent with default "
                       'values')
    group.add_argument('--stdin', action='store_true', help='Read values from standard input')
    parser.add_argument('-r', '--rate', metavar='N', type=float,
                        help='Repeat the call at a specific rate in Hz')
    parser.add_argument('--timeout', metavar='S', type=float, default=5.0,
                        help='Give up when the service is not available within S seconds '
                        '(default: %(default)s; 0 or less waits forever)')


def runs_in_daemon(args: argparse.Namespace) -> bool:
    """One call (no --rate), its request given on the command line (not --stdin): the daemon may
    run it for the CLI (ros2cli.daemon.verb_host)."""
    return args.rate is None and not args.stdin


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    import sys

    from ros2cli.interface_types import import_type
    from ros2cli.message_yaml import populate
    from ros2cli.node.direct import cli_node, spin_once
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
    with cli_node(context, spin_time=args.spin_time) as node:
        client = node.create_client(srv_type, args.service_name)
        if not _wait_for_service(client, started, args.timeout, context):
            return (f"Service '{args.service_name}' did not become available within "
                    f'{args.timeout:g} s (is its node running? see `ros2 service list`)')
        while True:
            print(f'requester: making request: {request!r}\n', flush=True, file=context.stdout)
            last_call = time.monotonic()
            future = client.call_async(request)
            while not future.done():
                spin_once(node, 0.1, context)
            if future.exception() is not None:
                raise CliError(f'Exception while calling service: {future.exception()!r}')
            print(f'response:\n{future.result()!r}\n', flush=True, file=context.stdout)
            if period is None:
                break
            remaining = last_call + period - time.monotonic()
            if remaining > 0:
                time.sleep(remaining)
    return 0


def _wait_for_service(client, started: float, timeout: float, context: VerbContext) -> bool:
    """Quietly give discovery three seconds, then say that we wait (as ros2cli does), bounded."""
    forever = timeout <= 0
    grace = started + (3.0 if forever else min(3.0, timeout))
    if client.wait_for_service(timeout_sec=max(0.0, grace - time.monotonic())):
        return True
    print('waiting for service to become available...', flush=True, file=context.stdout)
    if forever:
        while not client.wait_for_service(timeout_sec=1.0):
            context.check_cancelled()
        return True
    return client.wait_for_service(timeout_sec=max(0.0, started + timeout - time.monotonic()))
