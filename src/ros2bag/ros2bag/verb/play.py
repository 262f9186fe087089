"""ros2 bag play: publish a bag's messages again, with their recorded timing.

The verb checks the arguments and hands them to rosbag2_py.Player, which runs the player node
(rosbag2_py/_player.py).
"""

from __future__ import annotations

import argparse
import re

from ros2cli.verb_context import VerbContext

from ros2bag.api import (
    add_qos_overrides_argument,
    check_positive_float,
    load_qos_overrides,
    print_error,
)
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
    parser.add_argument('-e', '--regex', default='',
                        help='Play only topics and services matches with regular expression.')
    parser.add_argument('-x', '--exclude-regex', default='',
                        help='regular expressions to exclude topics and services from replay.')
    parser.add_argument('--exclude-topics', type=str, default=[], nargs='+',
                        help='Space-delimited list of topics not to play.')
    parser.add_argument('--exclude-services', type=str, default=[], nargs='+',
                        help='Space-delimited list of services not to play.')
    parser.add_argument('--read-ahead-queue-size', type=int, default=1000,
                        help='size of message queue rosbag tries to hold in memory to help '
                        'deterministic playback.')
    parser.add_argument('--storage-config-file', type=argparse.FileType('r'),
                        help='Path to a yaml file defining storage specific configurations. '
                        'See storage plugin documentation for the format of this file.')
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
    parser.add_argument('-p', '--start-paused', action='store_true',
                        help='Start the playback player in a paused state.')
    clock = parser.add_mutually_exclusive_group()
    clock.add_argument('--clock', type=check_positive_float, nargs='?', const=40.0, default=0.0,
                       help='Publish to /clock at a specific frequency in Hz, to act as a ROS '
                       'Time Source. Value must be positive. Defaults to not publishing.')
    clock.add_argument('--clock-topics', type=str, default=[], nargs='+',
                       help='List of topics separated by spaces that will trigger a /clock '
                       'update when a message is published on them')
    clock.add_argument('--clock-topics-all', action='store_true',
                       help='Publishes an update on /clock immediately before each replayed '
                       'message')
    parser.add_argument('--playback-duration', type=float, default=-1.0,
                        help='Playback duration, in seconds. Negative durations mark an '
                        'infinite playback. Default is -1.')
    until = parser.add_mutually_exclusive_group()
    until.add_argument('--playback-until-sec', type=float, default=-1.0,
                       help='Playback until timestamp, expressed in seconds since epoch. '
                       'Mutually exclusive argument with --playback-until-nsec.')
    until.add_argument('--playback-until-nsec', type=int, default=-1,
                       help='Playback until timestamp, expressed in nanoseconds since epoch. '
                       'Mutually exclusive argument with --playback-until-sec.')
    parser.add_argument('--wait-for-all-acked', type=int, default=-1,
                        help='Wait until all published messages are acknowledged by all '
                        'subscribers or until the timeout elapses in millisecond before play is '
                        'terminated. Negative timeout: a short wait of our own (Jazzy: none).')
    parser.add_argument('--disable-loan-message', action='store_true',
                        help='Disable to publish as loaned message (loans are not used here).')
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
    if args.read_ahead_queue_size < 1:
        return f'--read-ahead-queue-size must be at least 1, got {args.read_ahead_queue_size}'
    for pattern, flag in ((args.regex, '--regex'), (args.exclude_regex, '--exclude-regex')):
        try:
            re.compile(pattern)
        except re.error as error:
            return f"{flag}: '{pattern}' is not a valid regular expression ({error})"
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
    options.regex_to_filter = args.regex
    options.exclude_regex_to_filter = args.exclude_regex
    options.exclude_topics_to_filter = list(args.exclude_topics)
    options.exclude_service_events_to_filter = [s.rstrip('/') + '/_service_event'
                                                for s in args.exclude_services]
    options.read_ahead_queue_size = args.read_ahead_queue_size
    options.clock_publish_frequency = args.clock
    options.clock_publish_on_topic_publish = bool(args.clock_topics or args.clock_topics_all)
    options.clock_topics = list(args.clock_topics)
    options.playback_duration = args.playback_duration
    options.playback_until_timestamp = (
        int(args.playback_until_sec * 1e9) if args.playback_until_sec >= 0
        else args.playback_until_nsec)
    options.wait_acked_timeout = args.wait_for_all_acked
    options.disable_loan_message = args.disable_loan_message
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
    config = args.storage_config_file.name if args.storage_config_file else ''
    return StorageOptions(uri=args.bag_path, storage_id=args.storage,
                          storage_config_uri=config), options


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rosbag2_py import Player

    options = play_options(args)
    if isinstance(options, str):
        return options
    from ros2bag.api import exit_now

    try:
        Player(args.log_level).play(*options)
        result: int | str = 0
    except RuntimeError as failure:
        result = print_error(str(failure))
    exit_now(result, context)  # the player's context is shut down: skip Fast DDS's static teardown
