"""The storage files a bag is made of, written with the PyPI libraries: `.mcap` files with
`mcap`, `.db3` files with `rosbags`, set up as the storage config file says (_storage_config).
"""

from __future__ import annotations

import os
import sqlite3
from typing import Any

from rosbag2_py._definitions import full_text
from rosbag2_py._metadata_io import (
    BagMetadata,
    TopicInfo,
    dump_qos_profiles,
    dump_yaml,
    metadata_to_dict,
)
from rosbag2_py._storage_config import run_pragmas


class McapFile:
    """One `.mcap` file written with the `mcap` library, channels as Jazzy's plugin makes them."""

    def __init__(self, path: str, options: dict[str, Any]):
        """`options`: keyword arguments of mcap's Writer (see _storage_config)."""
        from mcap.writer import Writer

        self.stream = open(path, 'xb')  # kept open until close()
        self.writer = Writer(self.stream, **options)
        self.writer.start(profile='ros2', library='ros2bag (python mcap)')
        self.schemas: dict[str, int] = {}

    def add_topic(self, topic: TopicInfo) -> int:
        schema = self.schemas.get(topic.type)
        if schema is None:
            encoding, text = full_text(topic.type)
            schema = self.writer.register_schema(topic.type, encoding, text.encode())
            self.schemas[topic.type] = schema
        return self.writer.register_channel(
            topic.name, topic.serialization_format, schema,
            {'offered_qos_profiles': dump_qos_profiles(topic.offered_qos_profiles),
             'topic_type_hash': topic.type_description_hash})

    def write(self, channel: int, data: bytes, recv_ns: int, send_ns: int, sequence: int
              ) -> None:
        # MCAP's sequence is "a message counter assigned by the publisher": the DDS
        # publication sequence number fits it (Jazzy writes 0); it makes drops countable.
        self.writer.add_message(channel, log_time=recv_ns, data=data, publish_time=send_ns,
                                sequence=sequence & 0xFFFFFFFF)

    def size(self) -> int:
        return self.stream.tell()

    def flush(self) -> None:
        self.writer.flush()

    def close(self, meta: BagMetadata) -> None:
        self.writer.add_metadata('rosbag2', {'serialized_metadata': dump_yaml(
            metadata_to_dict(meta))})
        self.writer.finish()
        self.stream.flush()
        os.fsync(self.stream.fileno())
        self.stream.close()


class Sqlite3File:
    """The `.db3` file written with `rosbags` (its metadata.yaml is replaced by ours)."""

    def __init__(self, uri: str, pragmas: list[str]):
        """`pragmas`: `PRAGMA ...;` statements of the storage config file's `write` section,
        run once rosbags has created the tables (so `page_size` no longer changes anything)."""
        from rosbags.rosbag2 import StoragePlugin, Writer

        # rosbags creates the directory itself: hand it over empty.
        os.rmdir(uri)
        self.writer = Writer(uri, version=9, storage_plugin=StoragePlugin.SQLITE3)
        self.writer.open()
        self.name = os.path.basename(self.writer.storage.path)
        self.path = str(self.writer.storage.path)
        run_pragmas(self.writer.storage.conn, pragmas, sqlite3.Error)

    def add_topic(self, topic: TopicInfo) -> Any:
        from rosbags.interfaces import Qos

        # rosbags wants a hash even where the graph gave none.
        return self.writer.add_connection(
            topic.name, topic.type, msgdef=full_text(topic.type)[1],
            rihs01=topic.type_description_hash or 'RIHS01_' + '0' * 64,
            serialization_format=topic.serialization_format,
            offered_qos_profiles=[_rosbags_qos(Qos, p) for p in topic.offered_qos_profiles])

    def write(self, connection: Any, data: bytes, recv_ns: int, _send_ns: int, _sequence: int
              ) -> None:
        self.writer.write(connection, recv_ns, data)

    def size(self) -> int:
        return os.path.getsize(self.path)

    def flush(self) -> None:
        self.writer.storage.conn.commit()

    def close(self, meta: BagMetadata) -> None:
        self.writer.close()


def _rosbags_qos(qos_class: Any, profile: dict) -> Any:
    from rosbags.interfaces import (
        QosDurability,
        QosHistory,
        QosLiveliness,
        QosReliability,
        QosTime,
    )

    def time_of(value: dict) -> Any:
        return QosTime(sec=int(value['sec']), nsec=int(value['nsec']))

    return qos_class(
        history=QosHistory[profile['history'].upper()], depth=int(profile['depth']),
        reliability=QosReliability[profile['reliability'].upper()],
        durability=QosDurability[profile['durability'].upper()],
        deadline=time_of(profile['deadline']), lifespan=time_of(profile['lifespan']),
        liveliness=QosLiveliness[profile['liveliness'].upper()],
        liveliness_lease_duration=time_of(profile['liveliness_lease_duration']),
        avoid_ros_namespace_conventions=bool(profile['avoid_ros_namespace_conventions']))
