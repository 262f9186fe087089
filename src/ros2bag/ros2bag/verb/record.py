"""ros2 bag record: subscribe to topics (and service event topics) and write them to a bag.

The verb checks the arguments as Jazzy's and hands them to rosbag2_py.Recorder, which runs the
recorder node (rosbag2_py/_recorder.py).
"""

from __future__ import annotations

import argparse
import datetime
import os
import re

from ros2cli.verb_context import VerbContext

from ros2bag.api import add_qos_overrides_argument, load_qos_overrides, print_error
from ros2bag.verb import add_storage_preset_arguments

LOG_LEVELS = ['debug', 'info', 'warn', 'error', 'fatal']


def add_recorder_arguments(parser: argparse.ArgumentParser) -> None:
    from rosbag2_py import (
        get_default_storage_id,
        get_registered_compressors,
        get_registered_serializers,
    )

    parser.formatter_class = argparse.RawTextHelpFormatter
    parser.add_argument('-o', '--output', help='Destination of the bagfile to create, '
                        'defaults to a timestamped folder in the current directory.')
    add_storage_preset_arguments(parser, get_default_storage_id())
    topics = parser.add_mutually_exclusive_group()
    topics.add_argument('topics_positional', type=str, default=[], metavar='[Topic ...]',
                        nargs='*', help='Space-delimited list of topics to record. (deprecated)')
    topics.add_argument('--topics', type=str, default=[], metavar='Topic', nargs='+',
                        help='Space-delimited list of topics to record.')
    parser.add_argument('--services', '--service', type=str, metavar='ServiceName', nargs='+',
                        default=[], help='Space-delimited list of services to record.')
    parser.add_argument('--topic-types', nargs='+', default=[], metavar='TopicType',
                        help='Space-delimited list of topic types to record.')
    parser.add_argument('-a', '--all', action='store_true',
                        help='Record all topics and services (Exclude hidden topic).')
    parser.add_argument('--all-topics', action='store_true',
                        help='Record all topics (Exclude hidden topic).')
    parser.add_argument('--all-services', action='store_true',
                        help='Record all services via service event topics.')
    parser.add_argument('-e', '--regex', default='',
                        help='Record only topics and services containing provided regular '
                        'expression.')
    parser.add_argument('--exclude-regex', '--exclude', default='',
                        help='Exclude topics and services containing provided regular '
                        'expression.')
    parser.add_argument('--exclude-topic-types', type=str, default=[], nargs='+',
                        metavar='ExcludeTopicTypes',
                        help='Space-delimited list of topic types not being recorded.')
    parser.add_argument('--exclude-topics', type=str, metavar='Topic', nargs='+', default=[],
                        help='Space-delimited list of topics not being recorded.')
    parser.add_argument('--exclude-services', type=str, metavar='ServiceName', nargs='+',
                        default=[], help='Space-delimited list of services not being recorded.')
    parser.add_argument('--include-hidden-topics', action='store_true',
                        help='Discover and record hidden topics as well.')
    parser.add_argument('--include-unpublished-topics', action='store_true',
                        help='Discover and record topics which have no publisher. '
                        'Subscriptions on such topics will be made with default QoS unless '
                        'otherwise specified in a QoS overrides file.')
    parser.add_argument('--ignore-leaf-topics', action='store_true',
                        help='Ignore topics without a subscription.')
    parser.add_argument('-f', '--serialization-format', default='',
                        choices=sorted(get_registered_serializers()),
                        help='The rmw serialization format in which the messages are saved, '
                        'defaults to the rmw currently in use.')
    parser.add_argument('--no-discovery', action='store_true',
                        help='Disables topic auto discovery during recording: only topics '
                        'present at startup will be recorded.')
    parser.add_argument('-p', '--polling-interval', type=int, default=100,
                        help='Time in ms to wait between querying available topics for '
                        'recording.')
    add_qos_overrides_argument(parser)
    parser.add_argument('-b', '--max-bag-size', type=int, default=0,
                        help='Maximum size in bytes before the bagfile will be split. '
                        'Default: 0, splitting is disabled.')
    parser.add_argument('-d', '--max-bag-duration', type=int, default=0,
                        help='Maximum duration in seconds before the bagfile will be split. '
                        'Default: 0, splitting is disabled.')
    parser.add_argument('--disable-keyboard-controls', action='store_true',
                        help='disables keyboard controls for recorder')
    parser.add_argument('--start-paused', action='store_true',
                        help='Start the recorder in a paused state.')
    parser.add_argument('--use-sim-time', action='store_true',
                        help='Use simulation time for message timestamps by subscribing to the '
                        '/clock topic. Until first /clock message is received, no messages '
                        'will be written to bag.')
    parser.add_argument('--max-cache-size', type=int, default=100 * 1024 * 1024,
                        help='Maximum size (in bytes) of messages to hold in the snapshot '
                        'buffer (--snapshot-mode). Default: %(default)d. Without snapshot mode '
                        'messages are written as they come (no write cache here).')
    parser.add_argument('--snapshot-mode', action='store_true',
                        help='Enable snapshot mode. Messages will not be written to the bagfile '
                        'until the "/rosbag2_recorder/snapshot" service is called. e.g. \n '
                        'ros2 service call /rosbag2_recorder/snapshot '
                        'rosbag2_interfaces/Snapshot')
    parser.add_argument('--node-name', default='rosbag2_recorder',
                        help='Specify the recorder node name. Default is rosbag2_recorder.')
    parser.add_argument('--custom-data', type=str, metavar='KEY=VALUE', nargs='*', default=[],
                        help='Space-delimited list of key=value pairs stored in the metadata.')
    parser.add_argument('--log-level', type=str, default='info', choices=LOG_LEVELS,
                        help='Logging level.')
    parser.add_argument('--compression-queue-size', type=int, default=1,
                        help='Number of files or messages that may be queued for compression '
                        'before being dropped. Default is 1.')
    parser.add_argument('--compression-threads', type=int, default=0,
                        help='Number of files or messages that may be compressed in parallel. '
                        'Default is 0 (one per CPU core).')
    parser.add_argument('--compression-threads-priority', type=int, default=0,
                        help='Compression threads scheduling priority: the "nice" value, '
                        '-20 (highest) to +19 (lowest). Default is 0.')
    parser.add_argument('--compression-mode', type=str, default='none',
                        choices=['none', 'file', 'message'],
                        help='Choose mode of compression for the storage. Default: none.')
    parser.add_argument('--compression-format', type=str, default='',
                        choices=sorted(get_registered_compressors()),
                        help='Choose the compression format/algorithm. Has no effect if no '
                        'compression mode is chosen.')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_recorder_arguments(parser)
    parser.set_defaults(_main=main)


def validate_parsed_arguments(args: argparse.Namespace, uri: str) -> str | None:
    """Jazzy's argument checks, with its messages ('[ERROR] [ros2bag]: ...')."""
    if args.topics_positional:
        args.topics = args.topics_positional
    if not (args.all or args.all_topics or args.all_services or args.services or args.topics
            or args.topic_types or args.regex):
        return print_error('Need to specify at least one option out of --all, --all-topics, '
                           '--all-services, --services, --topics, --topic-types or --regex')
    if args.exclude_regex and not (args.all or args.all_topics or args.topic_types
                                   or args.all_services or args.regex):
        return print_error('--exclude-regex argument requires either --all, --all-topics, '
                           '--topic-types, --all-services or --regex')
    if args.exclude_topics and not (args.all or args.all_topics or args.topic_types
                                    or args.regex):
        return print_error('--exclude-topics argument requires either --all, --all-topics, '
                           '--topic-types or --regex')
    if args.exclude_topic_types and not (args.all or args.all_topics or args.regex):
        return print_error('--exclude-topic-types argument requires either --all, '
                           '--all-topics or --regex')
    if args.exclude_services and not (args.all or args.all_services or args.regex):
        return print_error('--exclude-services argument requires either --all, --all-services '
                           'or --regex')
    for pattern, flag in ((args.regex, '--regex'), (args.exclude_regex, '--exclude-regex')):
        try:
            re.compile(pattern)
        except re.error as error:
            return print_error(f"{flag}: '{pattern}' is not a valid regular expression "
                               f'({error})')
    if args.polling_interval <= 0:
        return print_error('--polling-interval must be a positive number of ms, got '
                           f'{args.polling_interval}')
    if args.max_bag_size < 0 or args.max_bag_duration < 0:
        return print_error('--max-bag-size and --max-bag-duration must be 0 (no split) or '
                           'positive')
    for pair in args.custom_data or []:
        if '=' not in pair:
            return print_error(f"--custom-data: '{pair}' is not KEY=VALUE")
    if os.path.isdir(uri):
        return print_error(f"Output folder '{uri}' already exists.")
    if args.use_sim_time and args.no_discovery:
        return print_error(
            '--use-sim-time and --no-discovery both set, but are incompatible settings. '
            'The /clock topic needs to be discovered to record with sim time.')
    if args.max_cache_size < 0:
        return print_error(f'--max-cache-size must be 0 or positive, got {args.max_cache_size}')
    if args.compression_format and args.compression_mode == 'none':
        return print_error('Invalid choice: Cannot specify compression format without a '
                           'compression mode.')
    if args.compression_mode != 'none' and not args.compression_format:
        return print_error('--compression-mode needs a --compression-format (zstd)')
    if args.compression_queue_size < 0:
        return print_error('Compression queue size must be at least 0.')
    return None


def _options(args: argparse.Namespace, uri: str, overrides: dict):
    from rosbag2_py import RecordOptions, StorageOptions

    storage = StorageOptions(
        uri=uri, storage_id=args.storage, max_bagfile_size=args.max_bag_size,
        max_bagfile_duration=args.max_bag_duration,
        storage_preset_profile=args.storage_preset_profile,
        storage_config_uri=args.storage_config_file.name if args.storage_config_file else '',
        max_cache_size=args.max_cache_size, snapshot_mode=args.snapshot_mode,
        custom_data=dict(pair.split('=', 1) for pair in args.custom_data or []))
    record = RecordOptions()
    record.all_topics = args.all or args.all_topics
    record.all_services = args.all or args.all_services
    record.is_discovery_disabled = args.no_discovery
    record.topics = list(args.topics)
    record.topic_types = list(args.topic_types)
    record.exclude_topic_types = list(args.exclude_topic_types)
    record.services = [s.rstrip('/') + '/_service_event' for s in args.services]
    record.exclude_topics = list(args.exclude_topics)
    record.exclude_service_events = [s.rstrip('/') + '/_service_event'
                                     for s in args.exclude_services]
    record.topic_polling_interval = datetime.timedelta(milliseconds=args.polling_interval)
    record.regex = args.regex
    record.exclude_regex = args.exclude_regex
    record.compression_mode = '' if args.compression_mode == 'none' else args.compression_mode
    record.compression_format = args.compression_format
    record.compression_queue_size = args.compression_queue_size
    record.compression_threads = args.compression_threads
    record.compression_threads_priority = args.compression_threads_priority
    record.topic_qos_profile_overrides = overrides
    record.include_hidden_topics = args.include_hidden_topics
    record.include_unpublished_topics = args.include_unpublished_topics
    record.ignore_leaf_topics = args.ignore_leaf_topics
    record.rmw_serialization_format = args.serialization_format or 'cdr'
    record.start_paused = args.start_paused
    record.use_sim_time = args.use_sim_time
    record.disable_keyboard_controls = args.disable_keyboard_controls
    return storage, record


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    uri = args.output or datetime.datetime.now().strftime('rosbag2_%Y_%m_%d-%H_%M_%S')
    error = validate_parsed_arguments(args, uri)
    if error:
        return error
    overrides = {}
    if args.qos_profile_overrides_path:
        try:
            overrides = load_qos_overrides(args.qos_profile_overrides_path)
        except ValueError as failure:
            return print_error(str(failure))
    from ros2bag.api import exit_now
    from rosbag2_py import Recorder

    storage, record = _options(args, uri, overrides)
    try:
        Recorder(args.log_level).record(storage, record, args.node_name)
        result: int | str = 0
    except RuntimeError as failure:
        result = print_error(str(failure))
    # The bag is closed and the context shut down (its log files flushed): only static
    # teardown is left, where Fast DDS's DomainParticipantFactory destructor sleeps 100 ms.
    # Exit now, so that a `ros2 bag info` typed right after Ctrl-C meets a finished recorder.
    exit_now(result, context)
