"""ros2 bag record: subscribe to topics (and service event topics) and write them to a bag.

Messages are stored as the CDR bytes the middleware delivers (raw subscriptions), stamped
with their reception time, as rosbag2 does. Topics are discovered every polling interval
until every requested one is subscribed.
"""

from __future__ import annotations

import argparse
import datetime
import os
import re
import time
from typing import Any

from ros2cli_lite.api import import_type, is_hidden

from ros2bag.metadata import (
    SERVICE_EVENT_SUFFIX,
    BagError,
    TopicInfo,
    one_line,
    qos_to_dict,
    request_qos_for_offers,
)
from ros2bag.session import SpaceKey, exit_now, make_executor, ros_node, spin_until
from ros2bag.storage import STORAGES, BagWriter

# Seconds a stopping recorder may spend recording what had arrived before the stop (each
# queue holds up to 1000 messages: a recorder far behind loses the rest, and exits in time).
DRAIN_BOUND = 0.25
MATCH_BOUND = 2.0  # seconds a new subscription may take to match its publishers
UNKNOWN_TOPIC_WARNING_AFTER = 5.0  # seconds without a requested topic before saying so


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-o', '--output', help='Destination of the bagfile to create, '
                        'defaults to a timestamped folder in the current directory.')
    parser.add_argument('-s', '--storage', default='mcap', choices=STORAGES,
                        help="Storage identifier to be used, defaults to 'mcap'.")
    topics = parser.add_mutually_exclusive_group()
    topics.add_argument('topics_positional', type=str, default=[], metavar='[Topic ...]',
                        nargs='*', help='Space-delimited list of topics to record.')
    topics.add_argument('--topics', type=str, default=[], metavar='Topic', nargs='+',
                        help='Space-delimited list of topics to record.')
    parser.add_argument('--services', '--service', type=str, metavar='ServiceName', nargs='+',
                        default=[], help='Space-delimited list of services to record.')
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
    parser.add_argument('--exclude-topics', type=str, metavar='Topic', nargs='+', default=[],
                        help='Space-delimited list of topics not being recorded.')
    parser.add_argument('--exclude-services', type=str, metavar='ServiceName', nargs='+',
                        default=[], help='Space-delimited list of services not being recorded.')
    parser.add_argument('--include-hidden-topics', action='store_true',
                        help='Discover and record hidden topics as well.')
    parser.add_argument('--no-discovery', action='store_true',
                        help='Disables topic auto discovery during recording: only topics '
                        'present at startup will be recorded.')
    parser.add_argument('-p', '--polling-interval', type=int, default=100,
                        help='Time in ms to wait between querying available topics for '
                        'recording.')
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
    parser.add_argument('--node-name', default='rosbag2_recorder',
                        help='Specify the recorder node name. Default is rosbag2_recorder.')
    parser.add_argument('--custom-data', type=str, metavar='KEY=VALUE', nargs='*', default=[],
                        help='Space-delimited list of key=value pairs stored in the metadata.')
    parser.set_defaults(_main=main)


def _absolute(name: str) -> str:
    return name if name.startswith('/') else '/' + name


def _validate(args: argparse.Namespace, uri: str) -> str | None:
    """Jazzy's argument checks, with its messages ('[ERROR] [ros2bag]: ...')."""
    topics = args.topics or args.topics_positional
    if not (args.all or args.all_topics or args.all_services or args.services or topics
            or args.regex):
        return ('Need to specify at least one option out of --all, --all-topics, '
                '--all-services, --services, --topics, --topic-types or --regex')
    if args.exclude_topics and not (args.all or args.all_topics or args.regex):
        return '--exclude-topics argument requires either --all, --all-topics or --regex'
    if args.exclude_services and not (args.all or args.all_services or args.regex):
        return '--exclude-services argument requires either --all, --all-services or --regex'
    for pattern, flag in ((args.regex, '--regex'), (args.exclude_regex, '--exclude-regex')):
        try:
            re.compile(pattern)
        except re.error as error:
            return f"{flag}: '{pattern}' is not a valid regular expression ({error})"
    if args.polling_interval <= 0:
        return f'--polling-interval must be a positive number of ms, got {args.polling_interval}'
    if args.max_bag_size < 0 or args.max_bag_duration < 0:
        return '--max-bag-size and --max-bag-duration must be 0 (no split) or positive'
    for pair in args.custom_data:
        if '=' not in pair:
            return f"--custom-data: '{pair}' is not KEY=VALUE"
    if os.path.isdir(uri):
        return f"Output folder '{uri}' already exists."
    return None


def main(args: argparse.Namespace) -> int | str:
    uri = args.output or datetime.datetime.now().strftime('rosbag2_%Y_%m_%d-%H_%M_%S')
    error = _validate(args, uri)
    if error:
        return f'[ERROR] [ros2bag]: {error}'
    try:
        writer = BagWriter(uri, args.storage, args.max_bag_size, args.max_bag_duration)
    except BagError as failure:
        return f'[ERROR] [ros2bag]: {failure}'
    writer.custom_data = dict(pair.split('=', 1) for pair in args.custom_data)
    with ros_node(args.node_name) as (node, stop):
        result = Recorder(node, writer, args).run(stop)
    # The bag is closed and the context shut down (its log files flushed): only static
    # teardown is left, where Fast DDS's DomainParticipantFactory destructor sleeps 100 ms.
    # Exit now, so that a `ros2 bag info` typed right after Ctrl-C meets a finished recorder.
    exit_now(result)


class Recorder:
    """The rosbag2_recorder node: discovery, raw subscriptions, pause, clean close."""

    def __init__(self, node: Any, writer: BagWriter, args: argparse.Namespace):
        self.node = node
        self.log = node.get_logger()
        self.writer = writer
        self.args = args
        self.paused = args.start_paused
        self.failed: str | None = None
        self.subscriptions: dict[str, Any] = {}
        self.skipped: set[str] = set()
        self.requested = [_absolute(t) for t in (args.topics or args.topics_positional)]
        self.requested_services = [_absolute(s).rstrip('/') + SERVICE_EVENT_SUFFIX
                                   for s in args.services]
        self.all_topics = args.all or args.all_topics
        self.all_services = args.all or args.all_services
        self.exclude_topics = {_absolute(t) for t in args.exclude_topics}
        self.exclude_services = {_absolute(s).rstrip('/') + SERVICE_EVENT_SUFFIX
                                 for s in args.exclude_services}
        self.regex = re.compile(args.regex) if args.regex else None
        self.exclude_regex = re.compile(args.exclude_regex) if args.exclude_regex else None
        self.discovery_timer: Any = None
        self.discovery_done = False
        self.started = time.monotonic()
        self.warned_missing = False
        self.keys = SpaceKey(self.toggle_paused)
        # ROS2BAG_EXECUTOR=events: rclpy's EventsExecutor, about a quarter of the CPU per
        # message, but it cannot hand the message info over (rclpy 7.1.6), so the reception
        # time is read in Python, late when the process is starved: play's timing suffers.
        self.events = os.environ.get('ROS2BAG_EXECUTOR') == 'events'
        self.taken = 0  # messages taken from the middleware, recorded or not

    # ---- what to record ----
    def _wanted(self, name: str) -> bool:
        if self.exclude_regex and self.exclude_regex.search(name):
            return False
        if name.endswith(SERVICE_EVENT_SUFFIX):
            if name in self.exclude_services:
                return False
            return (self.all_services or name in self.requested_services
                    or bool(self.regex and self.regex.search(name)))
        if name in self.exclude_topics:
            return False
        if name in self.requested:
            return True
        if is_hidden(name) and not self.args.include_hidden_topics:
            return False
        return self.all_topics or bool(self.regex and self.regex.search(name))

    def _explicit_only(self) -> bool:
        return not (self.all_topics or self.all_services or self.regex)

    # ---- discovery ----
    def discover(self) -> None:
        new: dict[str, int] = {}
        for name, types in self.node.get_topic_names_and_types():
            if name in self.subscriptions or name in self.skipped or not self._wanted(name):
                continue
            if len(types) != 1:
                self.log.warn(f"Topic '{name}' has several types ({', '.join(types)}): "
                              'not recorded')
                self.skipped.add(name)
                continue
            infos = self.node.get_publishers_info_by_topic(name)
            if not infos:
                continue  # a subscriber alone publishes nothing to record
            if self._subscribe(name, types[0], infos):
                new[name] = len(infos)
        self._wait_for_matches(new)
        wanted = self.requested + self.requested_services
        if self._explicit_only() and wanted and all(n in self.subscriptions for n in wanted):
            self.log.info('All requested topics are subscribed. Stopping discovery...')
            self._stop_discovery()
        elif (self._explicit_only() and not self.warned_missing
              and time.monotonic() - self.started > UNKNOWN_TOPIC_WARNING_AFTER):
            missing = [n for n in wanted if n not in self.subscriptions]
            self.warned_missing = True
            self.log.warn(f"Still waiting for publishers on {', '.join(missing)} (no such "
                          'topic in the graph yet); press Ctrl-C to stop')

    def _wait_for_matches(self, publishers: dict[str, int]) -> None:
        """Until new subscriptions are matched with the publishers seen (bounded).

        Better than rosbag2, where "Subscribed" can precede the DDS match by some
        milliseconds and a message sent meanwhile is not recorded.
        """
        deadline = time.monotonic() + MATCH_BOUND
        while publishers and time.monotonic() < deadline:
            if all(self.subscriptions[n].get_publisher_count() >= count
                   for n, count in publishers.items()):
                return
            time.sleep(0.005)

    def _stop_discovery(self) -> None:
        self.discovery_done = True
        if self.discovery_timer is not None:
            self.discovery_timer.cancel()
            self.node.destroy_timer(self.discovery_timer)
            self.discovery_timer = None

    def _subscribe(self, name: str, type_name: str, infos: list[Any]) -> bool:
        try:
            msg_class = import_type(type_name, type_name.split('/')[1]
                                    if type_name.count('/') == 2 else 'msg')
        except ValueError:
            self.log.warn(f"Topic '{name}' has type '{type_name}', which is not installed "
                          'here: not recorded')
            self.skipped.add(name)
            return False
        offers = [info.qos_profile for info in infos]
        self.writer.add_topic(TopicInfo(
            name=name, type=type_name, serialization_format='cdr',
            offered_qos_profiles=[qos_to_dict(q) for q in offers],
            type_description_hash=_type_hash(infos)))

        def on_message(data: bytes, info: dict) -> None:
            self._record(name, data, info)

        def on_message_events(data: bytes) -> None:
            stamp = time.time_ns()
            on_message(data, {'received_timestamp': stamp, 'source_timestamp': stamp})

        self.subscriptions[name] = self.node.create_subscription(
            msg_class, name, on_message_events if self.events else on_message,
            request_qos_for_offers(offers), raw=True)
        self.log.info(f"Subscribed to topic '{name}'")
        return True

    def _record(self, name: str, data: bytes, info: dict) -> None:
        self.taken += 1
        if self.paused or self.failed:
            return
        try:
            self.writer.write(name, data, info['received_timestamp'], info['source_timestamp'],
                              info.get('publication_sequence_number') or 0)
        except (OSError, BagError) as error:
            self.failed = f'Failed to write to bag: {one_line(error)}'

    # ---- pause ----
    def toggle_paused(self) -> None:
        self.paused = not self.paused
        self.log.info('Pausing recording.' if self.paused else 'Resuming recording.')

    # ---- main loop ----
    def run(self, stop: Any) -> int | str:
        if not self.args.disable_keyboard_controls and self.keys.active:
            self.log.info('Press SPACE for pausing/resuming')
            self.keys.start()
        self.log.info('Event publisher thread: Starting')
        self.log.info('Listening for topics...')
        executor = make_executor(self.node, self.events)
        try:
            self.discover()
            if not self.args.no_discovery and not self.discovery_done:
                self.discovery_timer = self.node.create_timer(
                    self.args.polling_interval / 1000.0, self.discover)
            if self.args.start_paused:
                self.log.info('Wait for recording: Press SPACE to start.')
            else:
                self.log.info('Recording...')
            flush_timer = self.node.create_timer(0.5, self._flush)
            spin_until(executor, self.node, lambda: stop.is_set() or bool(self.failed))
            stopped_ns = time.time_ns()
            flush_timer.cancel()
            self.node.destroy_timer(flush_timer)
            self._stop_discovery()
            self._drain(stopped_ns)
        finally:
            self.keys.close()
            self._stop_discovery()
            if not self.paused:
                self.paused = True
                self.log.info('Pausing recording.')
            for subscription in self.subscriptions.values():
                self.node.destroy_subscription(subscription)
            executor.shutdown(timeout_sec=1.0)
            closing_error = self._close()
        self.log.info('Event publisher thread: Exiting')
        self.log.info('Recording stopped')
        if self.failed or closing_error:
            hint = f"; recorded so far: make space, then 'ros2 bag reindex {self.writer.uri}'" \
                if closing_error and self.writer.storage == 'mcap' else ''
            return f'[ERROR] [ros2bag]: {self.failed or closing_error}{hint}'
        return 0

    def _drain(self, stopped_ns: int) -> None:
        """Record what had arrived when the stop was seen (acknowledged to its publishers).

        A stop request ends the spin loop between two messages; the subscriptions' queues
        may still hold messages their publishers count as delivered: record them too, taken
        straight from each queue up to the first one received after the stop. (Spinning the
        executor until nothing came took whatever kept arriving as well: with one topic at
        62.5 Hz the recorder drained until its 5 s bound, issue 24.)
        """
        from rclpy.exceptions import InvalidHandle

        deadline = time.monotonic() + DRAIN_BOUND
        for name, subscription in self.subscriptions.items():
            while not self.failed and time.monotonic() < deadline:
                try:
                    with subscription.handle:
                        taken = subscription.handle.take_message(subscription.msg_type, True)
                except InvalidHandle:
                    break
                if taken is None:
                    break
                data, info = taken
                if info['received_timestamp'] > stopped_ns:
                    break  # arrived after the stop, as everything queued behind it
                self._record(name, data, info)

    def _flush(self) -> None:
        if self.failed:
            return
        try:
            self.writer.flush()
        except OSError as error:
            self.failed = f'Failed to write to bag: {one_line(error)}'

    def _close(self) -> str | None:
        try:
            self.writer.close()
        except (OSError, BagError) as error:
            return f"Failed to close bag '{self.writer.uri}': {one_line(error)}"
        return None


def _type_hash(infos: list[Any]) -> str:
    """The one RIHS01 hash every publisher reports, else '' (as rosbag2)."""
    hashes = {_hash_string(info.topic_type_hash) for info in infos}
    hashes.discard('')
    return hashes.pop() if len(hashes) == 1 else ''


def _hash_string(value: Any) -> str:
    if value is None:
        return ''
    if isinstance(value, dict):
        version, digest = value.get('version', 0), value.get('value', b'')
    else:
        version, digest = getattr(value, 'version', 0), getattr(value, 'value', b'')
    if version != 1 or not digest:
        return ''
    return 'RIHS01_' + bytes(digest).hex()

