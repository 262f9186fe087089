"""SequentialWriter: a bag written message by message (one implementation with `ros2 bag
record`, see _bag_files.BagWriter).

A writer left open is closed when it is garbage-collected or, at the latest, when the
interpreter exits, as upstream's C++ destructor closes it: the pages' nodes never call close()
and are ended by Ctrl-C, and their bag still gets its metadata.yaml.
"""

from __future__ import annotations

import atexit
import weakref
from typing import Any

from rosbag2_py._bag_files import COMPRESSION_FORMATS, STORAGES, BagWriter
from rosbag2_py._compression_options import CompressionOptions, compression_mode_to_string
from rosbag2_py._metadata_io import BagError
from rosbag2_py._snapshot import SnapshotBuffer, check_snapshot_options
from rosbag2_py._storage import ConverterOptions, StorageOptions, TopicMetadata

_OPEN: weakref.WeakSet = weakref.WeakSet()


@atexit.register
def _close_all() -> None:
    for writer in list(_OPEN):
        writer.close()


def get_registered_writers() -> set[str]:
    return set(STORAGES)


def get_registered_compressors() -> set[str]:
    return set(COMPRESSION_FORMATS)


def get_registered_serializers() -> set[str]:
    return {'cdr'}


class SequentialWriter:
    def __init__(self) -> None:
        self._bag: BagWriter | None = None
        self._compression: CompressionOptions | None = None
        self._snapshot: SnapshotBuffer | None = None

    def open(self, storage_options: StorageOptions,
             converter_options: ConverterOptions | None = None) -> None:
        self.close()
        check_snapshot_options(storage_options)
        compression = self._compression
        try:
            self._bag = BagWriter(
                storage_options.uri, storage_options.storage_id,
                storage_options.max_bagfile_size, storage_options.max_bagfile_duration,
                compression_mode_to_string(compression.compression_mode) if compression else '',
                compression.compression_format if compression else '',
                storage_options.storage_preset_profile, storage_options.storage_config_uri)
        except BagError as error:
            raise RuntimeError(str(error)) from None
        self._snapshot = SnapshotBuffer(storage_options.max_cache_size) \
            if storage_options.snapshot_mode else None
        self._bag.custom_data = dict(storage_options.custom_data)
        if compression:
            self._bag.compression_threads = compression.compression_threads
            self._bag.compression_queue_size = compression.compression_queue_size
            self._bag.compression_priority = compression.compression_threads_priority
        _OPEN.add(self)

    def _writer(self) -> BagWriter:
        if self._bag is None:
            raise RuntimeError('Bag is not open. Call open() before writing.')
        return self._bag

    def create_topic(self, topic_metadata: TopicMetadata) -> None:
        self._writer().add_topic(topic_metadata._info())

    def remove_topic(self, topic_metadata: TopicMetadata) -> None:
        bag = self._writer()
        topic = bag.topics.get(topic_metadata.name)
        if topic is not None and not topic.message_count:
            del bag.topics[topic_metadata.name]

    def write(self, topic_name: str, message: Any, time_stamp: int,
              publish_time_stamp: int | None = None) -> None:
        """Store the serialized `message` (bytes) at receive time `time_stamp` (ns)."""
        bag = self._writer()
        if topic_name not in bag.topics:
            raise RuntimeError(f"Failed to write on topic '{topic_name}'. Call create_topic() "
                               'before first write.')
        if not isinstance(message, (bytes, bytearray, memoryview)):
            raise TypeError(f'write() takes the serialized message (bytes), not '
                            f'{type(message).__name__}: use rclpy.serialization.'
                            'serialize_message()')
        stamp = int(time_stamp)
        record = (topic_name, bytes(message), stamp,
                  stamp if publish_time_stamp is None else int(publish_time_stamp))
        if self._snapshot is not None:
            self._snapshot.push(record)
        else:
            bag.write(*record)

    def split_bagfile(self) -> None:
        try:
            self._writer().split()
        except BagError as error:
            raise RuntimeError(str(error)) from None

    def take_snapshot(self) -> bool:
        """Write what the snapshot buffer holds (snapshot mode only, else False)."""
        bag = self._writer()
        if self._snapshot is None:
            from rclpy.logging import get_logger
            get_logger('rosbag2_cpp').warning(
                'SequentialWriter take_snaphot called when snapshot mode is disabled')
            return False
        for record in self._snapshot.take():
            bag.write(*record)
        return True

    def close(self) -> None:
        if self._bag is not None:
            bag, self._bag = self._bag, None
            _OPEN.discard(self)
            bag.close()

    def __del__(self) -> None:
        try:
            self.close()
        except Exception:  # a finalizer must not raise; the bag stays as it was left
            pass


class SequentialCompressionWriter(SequentialWriter):
    def __init__(self, compression_options: CompressionOptions | None = None) -> None:
        super().__init__()
        self._compression = compression_options or CompressionOptions()
