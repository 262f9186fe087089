"""ros2 service echo: Echo a service."""

from __future__ import annotations

import argparse
import time

from ros2cli.echo_options import add_output_options, conversion_options
from ros2cli.verb_context import CliError, VerbContext

from ros2service.api import lookup

HELP = 'Echo a service'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('service_name', help="Name of the ROS service to echo (e.g. "
                        "'/add_two_ints')")
    parser.add_argument('service_type', nargs='?', help="Type of the ROS service (e.g. "
                        "'example_interfaces/srv/AddTwoInts')")
    parser.add_argument('--csv', action='store_true', default=False,
                        help='Output all recursive fields separated by commas (e.g. for plotting).')
    add_output_options(parser)


EVENT_TYPES = {0: 'REQUEST_SENT', 1: 'REQUEST_RECEIVED', 2: 'RESPONSE_SENT',
               3: 'RESPONSE_RECEIVED'}


# How long echo lets discovery find the event publishers before saying there are none.
ECHO_DISCOVERY = 2.0


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rclpy.qos import qos_profile_services_default
    from ros2cli.interface_types import import_type
    from ros2cli.message_yaml import to_yaml
    from ros2cli.node.direct import cli_node, spin_once

    from rosidl_runtime_py import message_to_csv, message_to_ordereddict
    type_name = args.service_type
    if type_name is None:
        found, _ = lookup(args, context=context)
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
    with cli_node(context, spin_time=args.spin_time) as node:
        topic = args.service_name.rstrip('/') + '/_service_event'

        options = conversion_options(args)

        def on_event(event) -> None:
            if args.csv:
                print(message_to_csv(event, **options), flush=True, file=context.stdout)
                return
            data = message_to_ordereddict(event, **options)
            data['info']['event_type'] = EVENT_TYPES.get(data['info']['event_type'],
                                                         data['info']['event_type'])
            print(to_yaml(data, args.flow_style) + '---', flush=True, file=context.stdout)

        subscription = node.create_subscription(srv_type.Event, topic, on_event,
                                                qos_profile_services_default)
        deadline = time.monotonic() + ECHO_DISCOVERY
        while subscription.get_publisher_count() < 1 and time.monotonic() < deadline:
            spin_once(node, 0.05, context)
        if subscription.get_publisher_count() < 1:
            print(f"No publishers on topic '{topic}'; is service introspection on the client "
                  'or server enabled?', flush=True, file=context.stdout)
        while True:
            spin_once(node, 0.5, context)
