"""ros2 bag play: publish a bag's messages again, with their recorded timing.

The verb checks the arguments and hands them to rosbag2_py.Player, which runs the player node
(rosbag2_py/_player.py).
"""

from __future__ import annotations

import argparse

from ros2bag.api import add_qos_overrides_argument, load_qos_overrides, print_error
from ros2bag.verb.record import LOG_LEVELS


def add_player_arguments(parser: argparse.ArgumentParser) -> None:
    """What `play` and `burst` take."""
    from rosbag2_py import get_registered_readers

    parser.add_argument('bag_path', help='Bag to open.')
    parser.add_argument('-s', '--storage', default='', choices=sorted(get_registered_readers()),
                        help='Storage implementation of bag. By default attempts to detect '
                        'automatically.')
    parser.add_argument('--topics', type=str, default=[], nargs='+',
                        help='Space-delimited list of topics to play.')
    parser.add_argument('--services', type=str, default=[], nargs='+',
                        help='Space-delimited list of services to play.')
    parser.add_argument('-r', '--rate', type=float, default=1.0,
                        help='rate at which to play back messages. Valid range > 0.0.')
    parser.add_argument('-l', '--loop', action='store_true',
                        help='enables loop playback when playing a bagfile: it starts back at '
                        'the beginning on reaching the end and plays indefinitely.')
    parser.add_argument('-m', '--remap', '--remappings', type=str, default=[], nargs='+',
                        help="list of topics to be remapped: in the form "
                        "'old_topic1:=new_topic1 old_topic2:=new_topic2 etc.'")
    parser.add_argument('-d', '--delay', type=float, default=0.0,
                        help='Sleep duration before play (each loop), in seconds. Negative '
                        'durations invalid.')
    parser.add_argument('--start-offset', type=float, default=0.0,
                        help='Start the playback player this many seconds into the bag file.')
    parser.add_argument('--start-paused', action='store_true',
                        help='Start the playback player in a paused state.')
    parser.add_argument('--disable-keyboard-controls', action='store_true',
                        help='disables keyboard controls for playback')
    parser.add_argument('--publish-service-requests', action='store_true',
                        help='Publish recorded service requests instead of recorded service '
                        'events')
    parser.add_argument('--service-requests-source', default='service_introspection',
                        choices=['service_introspection', 'client_introspection'],
                        help='Determine the source of the service requests to be replayed.')
    add_qos_overrides_argument(parser)
    parser.add_argument('--log-level', type=str, default='info', choices=LOG_LEVELS,
                        help='Logging level.')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_player_arguments(parser)
    parser.set_defaults(_main=main)


def _validate(args: argparse.Namespace) -> str | None:
    if not args.rate > 0.0:
        return f'--rate must be greater than 0.0, got {args.rate:g}'
    if args.delay < 0.0:
        return f'--delay must be 0 or positive, got {args.delay:g}'
    if args.start_offset < 0.0:
        return f'--start-offset must be 0 or positive, got {args.start_offset:g}'
    for pair in args.remap:
        old, sep, new = pair.partition(':=')
        if not sep or not old or not new:
            return f"--remap: '{pair}' is not old_topic:=new_topic"
    return None


def play_options(args: argparse.Namespace):
    """(StorageOptions, PlayOptions) of `play`/`burst` arguments, or the error line."""
    from rosbag2_py import PlayOptions, ServiceRequestsSource, StorageOptions

    error = _validate(args)
    if error:
        return print_error(error)
    overrides = {}
    if args.qos_profile_overrides_path:
        try:
            overrides = load_qos_overrides(args.qos_profile_overrides_path)
        except ValueError as failure:
            return print_error(str(failure))
    options = PlayOptions()
    options.rate = args.rate
    options.loop = args.loop
    options.topics_to_filter = list(args.topics)
    options.services_to_filter = [s.rstrip('/') + '/_service_event' for s in args.services]
    options.topic_remapping_options = list(args.remap)
    options.delay = args.delay
    options.start_offset = args.start_offset
    options.start_paused = args.start_paused
    options.disable_keyboard_controls = args.disable_keyboard_controls
    options.publish_service_requests = args.publish_service_requests
    options.service_requests_source = (
        ServiceRequestsSource.SERVICE_INTROSPECTION
        if args.service_requests_source == 'service_introspection'
        else ServiceRequestsSource.CLIENT_INTROSPECTION)
    options.topic_qos_profile_overrides = overrides
    return StorageOptions(uri=args.bag_path, storage_id=args.storage), options


def main(args: argparse.Namespace) -> int | str:
    from rosbag2_py import Player

    options = play_options(args)
    if isinstance(options, str):
        return options
    from rosbag2_py._session import exit_now

    try:
        Player(args.log_level).play(*options)
        result: int | str = 0
    except RuntimeError as failure:
        result = print_error(str(failure))
    exit_now(result)  # the player's context is shut down: skip Fast DDS's static teardown
