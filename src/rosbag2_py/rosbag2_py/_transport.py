"""Recorder and Player (upstream's `_transport`): what `ros2 bag record/play/burst` run.

record() and play() block until the bag is done or cancel() is called (from another thread,
or SIGINT/SIGTERM when they run in the main thread). Each runs its node in a context of its
own, so the caller's rclpy context is neither needed nor touched.
"""

from __future__ import annotations

import datetime
import enum
import threading
from typing import Any, ClassVar

from rosbag2_py._bag_files import BagReader, BagWriter
from rosbag2_py._compression_options import compression_mode_from_string
from rosbag2_py._metadata_io import BagError
from rosbag2_py._session import ros_node
from rosbag2_py._snapshot import SnapshotBuffer, check_snapshot_options
from rosbag2_py._storage import StorageOptions

LOG_LEVELS = ('debug', 'info', 'warn', 'error', 'fatal')


class ServiceRequestsSource(enum.IntEnum):
    SERVICE_INTROSPECTION = 0
    CLIENT_INTROSPECTION = 1


class RecordOptions:
    def __init__(self) -> None:
        self.all_topics = False
        self.all_services = False
        self.is_discovery_disabled = False
        self.topics: list[str] = []
        self.topic_types: list[str] = []
        self.exclude_topic_types: list[str] = []
        self.services: list[str] = []  # service event topics (`/x/_service_event`)
        self.exclude_topics: list[str] = []
        self.exclude_service_events: list[str] = []
        self.rmw_serialization_format = 'cdr'
        self.topic_polling_interval = datetime.timedelta(milliseconds=100)
        self.regex = ''
        self.exclude_regex = ''
        self.node_prefix = ''
        self.compression_mode = ''
        self.compression_format = ''
        self.compression_queue_size = 1
        self.compression_threads = 0
        self.compression_threads_priority = 0
        self.topic_qos_profile_overrides: dict[str, Any] = {}
        self.include_hidden_topics = False
        self.include_unpublished_topics = False
        self.ignore_leaf_topics = False
        self.start_paused = False
        self.use_sim_time = False
        self.disable_keyboard_controls = False


class PlayOptions:
    def __init__(self) -> None:
        self.read_ahead_queue_size = 1000
        self.node_prefix = ''
        self.rate = 1.0
        self.topics_to_filter: list[str] = []
        self.services_to_filter: list[str] = []
        self.regex_to_filter = ''
        self.exclude_regex_to_filter = ''
        self.exclude_topics_to_filter: list[str] = []
        self.exclude_service_events_to_filter: list[str] = []
        self.topic_qos_profile_overrides: dict[str, Any] = {}
        self.loop = False
        self.topic_remapping_options: list[str] = []
        self.clock_publish_frequency = 0.0
        self.clock_publish_on_topic_publish = False
        self.clock_topics: list[str] = []
        self.delay = 0.0
        self.playback_duration = -1.0
        self.playback_until_timestamp = -1
        self.start_paused = False
        self.start_offset = 0.0
        self.disable_keyboard_controls = False
        self.wait_acked_timeout = -1
        self.disable_loan_message = False
        self.publish_service_requests = False
        self.service_requests_source = ServiceRequestsSource.SERVICE_INTROSPECTION


def _check_level(log_level: str) -> str:
    if log_level.lower() not in LOG_LEVELS:
        raise RuntimeError(f"Invalid log level '{log_level}' (allowed: "
                           f"{', '.join(LOG_LEVELS)})")
    return log_level.lower()


def _set_level(node: Any, level: str) -> None:
    from rclpy.logging import LoggingSeverity
    node.get_logger().set_level(getattr(LoggingSeverity, level.upper()))


class _Cancellable:
    """cancel() ends whatever record()/play() runs now (upstream's static cancel)."""

    _running: ClassVar[set[threading.Event]] = set()

    @staticmethod
    def cancel() -> None:
        for stop in list(_Cancellable._running):
            stop.set()

    @staticmethod
    def _stop_event() -> threading.Event:
        """Registered before anything slow starts: a cancel() from the caller's thread right
        after starting record()/play() in another one must not pass unseen."""
        stop = threading.Event()
        _Cancellable._running.add(stop)
        return stop

    @staticmethod
    def _run(name: str, level: str, stop: threading.Event, body: Any,
             use_sim_time: bool = False, meet: bool = False) -> str | None:
        try:
            with ros_node(name, stop, use_sim_time, meet) as (node, _stop):
                _set_level(node, level)
                return body(node, stop)
        finally:
            _Cancellable._running.discard(stop)


class Recorder(_Cancellable):
    def __init__(self, log_level: str = 'info') -> None:
        self.log_level = _check_level(log_level)

    def record(self, storage_options: StorageOptions, record_options: RecordOptions,
               node_name: str = 'rosbag2_recorder') -> None:
        """Record until cancel() (or SIGINT/SIGTERM); RuntimeError naming what failed."""
        from rosbag2_py._recorder import RecorderNode

        if record_options.use_sim_time and record_options.is_discovery_disabled:
            raise RuntimeError(
                'use_sim_time and is_discovery_disabled both set, but are incompatible '
                'settings. The /clock topic needs to be discovered to record with sim time.')
        check_snapshot_options(storage_options)
        stop = self._stop_event()
        mode = record_options.compression_mode
        try:
            writer = BagWriter(
                storage_options.uri, storage_options.storage_id,
                storage_options.max_bagfile_size, storage_options.max_bagfile_duration,
                compression_mode_from_string(mode).name if mode else '',
                record_options.compression_format, storage_options.storage_preset_profile,
                storage_options.storage_config_uri)
        except (BagError, ValueError) as error:
            self._running.discard(stop)
            raise RuntimeError(str(error)) from None
        writer.custom_data = dict(storage_options.custom_data)
        writer.compression_priority = record_options.compression_threads_priority
        writer.compression_threads = record_options.compression_threads
        writer.compression_queue_size = record_options.compression_queue_size

        def body(node: Any, stop: threading.Event) -> str | None:
            if writer.compression_mode:
                node.get_logger().debug('Setting compression thread priority to '
                                        f'{record_options.compression_threads_priority}')
            snapshot = SnapshotBuffer(storage_options.max_cache_size) \
                if storage_options.snapshot_mode else None
            return RecorderNode(node, writer, record_options, snapshot).run(stop)

        # The recorder subscribes to what is already there before it says "Recording...",
        # as rosbag2: its node first meets the graph.
        failure = self._run(record_options.node_prefix + node_name, self.log_level, stop, body,
                            record_options.use_sim_time, meet=True)
        if failure:
            raise RuntimeError(failure)


class Player(_Cancellable):
    def __init__(self, log_level: str = 'info') -> None:
        self.log_level = _check_level(log_level)

    def _start(self, storage_options: StorageOptions, play_options: PlayOptions,
               burst: int | None) -> None:
        from rosbag2_py._player import PlayerNode

        if not play_options.rate > 0.0:
            raise RuntimeError(f'rate must be greater than 0.0, got {play_options.rate:g}')
        stop = self._stop_event()
        try:
            reader = BagReader(storage_options.uri, storage_options.storage_config_uri)
        except BagError as error:
            self._running.discard(stop)
            raise RuntimeError(str(error)) from None
        try:
            failure = self._run(
                play_options.node_prefix + 'rosbag2_player', self.log_level, stop,
                lambda node, stop: PlayerNode(node, reader, play_options, burst).run(stop))
        finally:
            reader.close()
        if failure:
            raise RuntimeError(failure)

    def play(self, storage_options: StorageOptions, play_options: PlayOptions) -> None:
        self._start(storage_options, play_options, None)

    def burst(self, storage_options: StorageOptions, play_options: PlayOptions,
              num_messages: int = 0) -> None:
        """Publish `num_messages` (0: all) as fast as possible."""
        self._start(storage_options, play_options, max(0, int(num_messages)))


def bag_rewrite(input_options: list[StorageOptions], output_options_path: str) -> None:
    from rosbag2_py._rewrite import rewrite
    rewrite(input_options, output_options_path)
