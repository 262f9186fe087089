"""The rosbag2_recorder node: discovery, raw subscriptions, pause, clean close.

Messages are stored as the CDR bytes the middleware delivers (raw subscriptions), stamped
with their reception time, as rosbag2 does, or with the latest /clock time with
use_sim_time (then nothing is subscribed before the first /clock message). Topics are
discovered every polling interval until every requested one is subscribed. In snapshot mode
messages go to a ring buffer that `~/snapshot` writes out. `rosbag2_py.Recorder` and
`ros2 bag record` run it; its services are in _recorder_services.
"""

from __future__ import annotations

import os
import re
import time
from typing import Any

from ros2cli.interface_types import import_type
from ros2cli.names import is_hidden

from rosbag2_py._bag_files import BagWriter
from rosbag2_py._metadata_io import (
    SERVICE_EVENT_SUFFIX,
    BagError,
    TopicInfo,
    event_topic,
    one_line,
    qos_to_dict,
    request_qos_for_offers,
)
from rosbag2_py._recorder_services import RecorderServices
from rosbag2_py._session import SpaceKey, make_executor, spin_until
from rosbag2_py._snapshot import SnapshotBuffer

# Seconds a stopping recorder may spend recording what had arrived before the stop (each
# queue holds up to 1000 messages: a recorder far behind loses the rest, and exits in time).
DRAIN_BOUND = 0.25
MATCH_BOUND = 2.0  # seconds a new subscription may take to match its publishers
UNKNOWN_TOPIC_WARNING_AFTER = 5.0  # seconds without a requested topic before saying so


def _absolute(name: str) -> str:
    return name if name.startswith('/') else '/' + name


class RecorderNode:
    """What a recording does with its node; `options` is a rosbag2_py.RecordOptions."""

    def __init__(self, node: Any, writer: BagWriter, options: Any,
                 snapshot: SnapshotBuffer | None = None):
        self.node = node
        self.snapshot = snapshot  # snapshot mode: messages wait here for ~/snapshot
        # use_sim_time: stamps are the node's ROS time, which /clock drives; nothing is
        # subscribed before the first /clock message (as Jazzy: time 0 would come first).
        self.sim_time = bool(options.use_sim_time)
        self.clock_started = not self.sim_time
        self.log = node.get_logger()
        self.writer = writer
        self.options = options
        self.paused = options.start_paused
        self.failed: str | None = None
        self.subscriptions: dict[str, Any] = {}
        self.skipped: set[str] = set()
        self.requested = [_absolute(t) for t in options.topics]
        self.requested_services = [event_topic(s) for s in options.services]
        self.all_topics = options.all_topics
        self.all_services = options.all_services
        self.topic_types = set(options.topic_types)
        self.exclude_topic_types = set(options.exclude_topic_types)
        self.exclude_topics = {_absolute(t) for t in options.exclude_topics}
        self.exclude_services = {event_topic(s) for s in options.exclude_service_events}
        self.regex = re.compile(options.regex) if options.regex else None
        self.exclude_regex = re.compile(options.exclude_regex) if options.exclude_regex else None
        self.overrides = dict(options.topic_qos_profile_overrides)
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
    def _wanted(self, name: str, types: list[str]) -> bool:
        if self.exclude_regex and self.exclude_regex.search(name):
            return False
        if self.exclude_topic_types.intersection(types):
            return False
        if name.endswith(SERVICE_EVENT_SUFFIX):
            if name in self.exclude_services:
                return False
            return (self.all_services or name in self.requested_services
                    or bool(self.regex and self.regex.search(name)))
        if name in self.exclude_topics:
            return False
        if name in self.requested or self.topic_types.intersection(types):
            return True
        if is_hidden(name) and not self.options.include_hidden_topics:
            return False
        return self.all_topics or bool(self.regex and self.regex.search(name))

    def _explicit_only(self) -> bool:
        return not (self.all_topics or self.all_services or self.regex or self.topic_types)

    # ---- discovery ----
    def discover(self) -> None:
        if not self.clock_started:
            if self.node.get_clock().now().nanoseconds == 0:
                return
            self.clock_started = True
            self.log.info('Sim time /clock found, starting recording.')
        new: dict[str, int] = {}
        for name, types in self.node.get_topic_names_and_types():
            if name in self.subscriptions or name in self.skipped or not self._wanted(name, types):
                continue
            if len(types) != 1:
                self.log.warn(f"Topic '{name}' has several types ({', '.join(types)}): "
                              'not recorded')
                self.skipped.add(name)
                continue
            infos = self.node.get_publishers_info_by_topic(name)
            if not infos and not self.options.include_unpublished_topics:
                continue  # a subscriber alone publishes nothing to record
            if self.options.ignore_leaf_topics and not self.node.count_subscribers(name):
                continue  # a leaf topic, nobody subscribed (looked at again next pass)
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
            name=name, type=type_name,
            serialization_format=self.options.rmw_serialization_format or 'cdr',
            offered_qos_profiles=[qos_to_dict(q) for q in offers],
            type_description_hash=_type_hash(infos)))

        def on_message(data: bytes, info: dict) -> None:
            self._record(name, data, info)

        def on_message_events(data: bytes) -> None:
            stamp = time.time_ns()
            on_message(data, {'received_timestamp': stamp, 'source_timestamp': stamp})

        qos = self.overrides.get(name)
        if qos is not None:
            self.log.info(f'Overriding subscription profile for {name}')
        else:
            qos = request_qos_for_offers(offers)
        self.subscriptions[name] = self.node.create_subscription(
            msg_class, name, on_message_events if self.events else on_message, qos, raw=True)
        self.log.info(f"Subscribed to topic '{name}'")
        return True

    def _record(self, name: str, data: bytes, info: dict) -> None:
        self.taken += 1
        if self.paused or self.failed:
            return
        stamp = self.node.get_clock().now().nanoseconds if self.sim_time \
            else info['received_timestamp']
        message = (name, data, stamp, info['source_timestamp'],
                   info.get('publication_sequence_number') or 0)
        if self.snapshot is not None:
            self.snapshot.push(message)
            return
        self._write(message)

    def _write(self, message: tuple) -> None:
        try:
            self.writer.write(*message)
        except (OSError, BagError) as error:
            self.failed = f'Failed to write to bag: {one_line(error)}'

    def take_snapshot(self) -> bool:
        """Write what the snapshot buffer holds (`~/snapshot`); False outside snapshot mode."""
        if self.snapshot is None:
            return False
        for message in self.snapshot.take():
            self._write(message)
        return not self.failed

    # ---- pause ----
    def toggle_paused(self) -> None:
        self.paused = not self.paused
        self.log.info('Pausing recording.' if self.paused else 'Resuming recording.')

    def pause(self) -> None:
        if self.paused:
            self.log.debug('Recorder is already in pause state.')
        else:
            self.paused = True
            self.log.info('Pausing recording.')

    def resume(self) -> None:
        if not self.paused:
            self.log.debug('Already in the recording.')
        else:
            self.paused = False
            self.log.info('Resuming recording.')

    # ---- main loop ----
    def run(self, stop: Any) -> str | None:
        if not self.options.disable_keyboard_controls and self.keys.active:
            self.log.info('Press SPACE for pausing/resuming')
            self.keys.start()
        services = RecorderServices(self)
        self.log.info('Event publisher thread: Starting')
        self.log.info('Listening for topics...')
        executor = make_executor(self.node, self.events)
        try:
            if self.sim_time:
                self.log.info('use_sim_time set, waiting for /clock before starting recording...')
            self.discover()
            if not self.options.is_discovery_disabled and not self.discovery_done:
                self.discovery_timer = self.node.create_timer(
                    _seconds(self.options.topic_polling_interval), self.discover)
            if self.options.start_paused:
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
            services.close()  # after the close: its write_split event is published
        self.log.info('Event publisher thread: Exiting')
        self.log.info('Recording stopped')
        if self.failed or closing_error:
            hint = f"; recorded so far: make space, then 'ros2 bag reindex {self.writer.uri}'" \
                if closing_error and self.writer.storage == 'mcap' else ''
            return f'{self.failed or closing_error}{hint}'
        return None

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



def _seconds(interval: Any) -> float:
    """A polling interval given as datetime.timedelta (upstream) or in milliseconds."""
    if hasattr(interval, 'total_seconds'):
        return max(0.001, interval.total_seconds())
    return max(0.001, float(interval) / 1000.0)
