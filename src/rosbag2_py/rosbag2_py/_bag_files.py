"""Bag files on the PyPI libraries: MCAP written with `mcap`, SQLite3 written with `rosbags`,
both read with `rosbags`. Nothing here encodes a file format itself.

The writers keep what was acknowledged safe: MCAP chunks are finished and flushed, SQLite3
transactions committed, at least every FLUSH_PERIOD seconds, so a recorder killed without
warning (SIGKILL, power loss) loses at most that much; `reindex` then rebuilds the bag.
"""

from __future__ import annotations

import os
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from rosbag2_py._compression import CompressionPool, compress_file
from rosbag2_py._definitions import full_text
from rosbag2_py._metadata_io import (
    BagError,
    BagMetadata,
    TopicInfo,
    dump_qos_profiles,
    dump_yaml,
    metadata_to_dict,
    one_line,
    read_metadata_file,
    write_metadata_file,
)

STORAGES = ('mcap', 'sqlite3')
DEFAULT_STORAGE = 'mcap'
COMPRESSION_MODES = ('', 'MESSAGE', 'FILE')
COMPRESSION_FORMATS = ('zstd',)
# Each storage's preset profiles (`--storage-preset-profile`): MCAP's compress its chunks with
# zstd, SQLite3's `resilient` commits every write (rosbag2's presets of the same names).
STORAGE_PRESETS = {'mcap': ('fastwrite', 'zstd_fast', 'zstd_small'), 'sqlite3': ('resilient',)}
FLUSH_PERIOD = 0.5  # seconds: the most a SIGKILLed recorder can lose
MCAP_CHUNK_SIZE = 768 * 1024  # mcap-cpp's default, which Jazzy's plugin keeps


# --------------------------------------------------------------------------------------
# Writing
# --------------------------------------------------------------------------------------

@dataclass
class _FileStats:
    path: str
    start: int = 0
    end: int = 0
    count: int = 0

    def add(self, stamp: int) -> None:
        self.start = stamp if self.count == 0 else min(self.start, stamp)
        self.end = max(self.end, stamp)
        self.count += 1


class BagWriter:
    """A rosbag2 directory being recorded: topics, messages, files, metadata.yaml."""

    def __init__(self, uri: str, storage: str, max_bytes: int = 0, max_seconds: int = 0,
                 compression_mode: str = '', compression_format: str = '', preset: str = ''):
        storage = storage or DEFAULT_STORAGE
        if storage not in STORAGES:
            raise BagError(f"Unknown storage id '{storage}' (allowed: {', '.join(STORAGES)})")
        if preset and preset not in STORAGE_PRESETS[storage]:
            raise BagError(f"Unknown storage preset profile '{preset}' for {storage} (allowed: "
                           f"{', '.join(STORAGE_PRESETS[storage])})")
        self.preset = preset
        if (max_bytes or max_seconds) and storage != 'mcap':
            raise BagError('Splitting (--max-bag-size/--max-bag-duration) is available with '
                           "'-s mcap' only here")
        compression_mode = compression_mode.upper() if compression_mode else ''
        if compression_mode == 'NONE':
            compression_mode = ''
        if compression_mode not in COMPRESSION_MODES:
            raise BagError(f"Unknown compression mode '{compression_mode}' (allowed: none, "
                           'message, file)')
        if compression_mode and compression_format not in COMPRESSION_FORMATS:
            raise BagError(f"Unknown compression format '{compression_format}' (allowed: "
                           f"{', '.join(COMPRESSION_FORMATS)})")
        self.compression_mode = compression_mode
        self.compression_format = compression_format if compression_mode else ''
        # rosbag2's compression threads (see _compression.py), started at the first use.
        self.compression_priority = 0
        self.compression_threads = 0
        self.compression_queue_size = 1
        self._pool: CompressionPool | None = None
        self._lock = threading.RLock()  # compression threads write and close files too
        self.uri = uri
        self.storage = storage
        self.max_bytes = max_bytes
        self.max_ns = max_seconds * 1_000_000_000
        self.topics: dict[str, TopicInfo] = {}
        self.files: list[_FileStats] = []
        self._last_flush = time.monotonic()
        self._backend: Any = None
        self._handles: dict[str, Any] = {}
        self.custom_data: dict[str, str] = {}
        self.closed = False
        try:
            os.makedirs(uri)
        except FileExistsError:
            raise BagError(f"Output folder '{uri}' already exists.") from None
        except OSError as error:
            raise BagError(f"Cannot create output folder '{uri}': {one_line(error)}") from None
        self._open_file()

    # ---- files ----
    def _open_file(self) -> None:
        base = os.path.basename(os.path.normpath(self.uri))
        try:
            if self.storage == 'mcap':
                name = f'{base}_{len(self.files)}.mcap'
                self._backend = _McapFile(os.path.join(self.uri, name),
                                          self.preset.startswith('zstd'))
            else:
                self._backend = _Sqlite3File(self.uri)
                name = self._backend.name
        except OSError as error:
            raise BagError(f"Cannot write to '{self.uri}': {one_line(error)}") from None
        self.files.append(_FileStats(name))
        self._handles = {}
        for topic in self.topics.values():
            self._handles[topic.name] = self._backend.add_topic(topic)

    def add_topic(self, topic: TopicInfo) -> None:
        if topic.name in self.topics:
            return
        self.topics[topic.name] = topic
        self._handles[topic.name] = self._backend.add_topic(topic)

    def write(self, topic: str, data: bytes, recv_ns: int, send_ns: int,
              sequence: int = 0) -> None:
        """One message; `sequence` is the publisher's sequence number (0: unknown)."""
        if self.compression_mode == 'MESSAGE':
            pool = self._compression()
            pool.put_message(topic, bytes(data), recv_ns, send_ns, sequence)
            for compressed in pool.take_compressed():
                self._store(*compressed)
        else:
            self._store(topic, data, recv_ns, send_ns, sequence)

    def _compression(self) -> CompressionPool:
        if self._pool is None:
            self._pool = CompressionPool(self.compression_threads, self.compression_queue_size,
                                         self.compression_priority)
        return self._pool

    def _store(self, topic: str, data: bytes, recv_ns: int, send_ns: int,
               sequence: int) -> None:
        with self._lock:
            current = self.files[-1]
            if current.count and (
                    (self.max_ns and recv_ns - current.start >= self.max_ns)
                    or (self.max_bytes and self._backend.size() >= self.max_bytes)):
                self.split()
                current = self.files[-1]
            self._backend.write(self._handles[topic], data, recv_ns, send_ns, sequence)
            current.add(recv_ns)
            self.topics[topic].message_count += 1
            now = time.monotonic()
            if now - self._last_flush >= FLUSH_PERIOD or self.preset == 'resilient':
                self.flush()

    def split(self) -> None:
        """Close the current storage file (compressed in the background in FILE mode)."""
        with self._lock:
            closed = self.files[-1]
            self._backend.close(self._metadata())
            if self.compression_mode == 'FILE':
                self._compression().put_file(lambda: self._compress(closed))
            self._open_file()

    def _compress(self, stats: _FileStats) -> None:
        compress_file(os.path.join(self.uri, stats.path))
        with self._lock:
            stats.path += '.zstd'

    def flush(self) -> None:
        with self._lock:
            self._last_flush = time.monotonic()
            self._backend.flush()

    def _metadata(self) -> BagMetadata:
        files = [f for f in self.files if f.count] or self.files[:1]
        counted = [f for f in files if f.count]
        start = min((f.start for f in counted), default=0)
        end = max((f.end for f in counted), default=0)
        return BagMetadata(
            storage_identifier=self.storage,
            relative_file_paths=[f.path for f in self.files],
            topics=list(self.topics.values()),
            starting_time_ns=start, duration_ns=end - start,
            message_count=sum(f.count for f in self.files),
            file_counts=[(f.path, f.start, f.end - f.start, f.count) for f in self.files],
            custom_data=self.custom_data, compression_format=self.compression_format,
            compression_mode=self.compression_mode)

    def close(self) -> None:
        """Finish the storage file and write metadata.yaml (idempotent); queued messages are
        compressed and written first, and every file compressed in FILE mode."""
        if self.closed:
            return
        self.closed = True
        if self.compression_mode == 'MESSAGE' and self._pool is not None:
            self._pool.close()
            for compressed in self._pool.take_compressed():
                self._store(*compressed)
        with self._lock:
            self._backend.close(self._metadata())
        if self.compression_mode == 'FILE':
            pool = self._compression()
            last = self.files[-1]
            pool.put_file(lambda: self._compress(last))
            pool.close()
        write_metadata_file(self.uri, self._metadata())


def _zstd_decompress(data: bytes) -> bytes:
    import zstandard
    return zstandard.ZstdDecompressor().decompress(bytes(data))


class _McapFile:
    """One `.mcap` file written with the `mcap` library, channels as Jazzy's plugin makes them."""

    def __init__(self, path: str, zstd_chunks: bool = False):
        from mcap.writer import CompressionType, Writer

        self.stream = open(path, 'xb')  # kept open until close()
        self.writer = Writer(self.stream, chunk_size=MCAP_CHUNK_SIZE, compression=(
            CompressionType.ZSTD if zstd_chunks else CompressionType.NONE))
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


class _Sqlite3File:
    """The `.db3` file written with `rosbags` (its metadata.yaml is replaced by ours)."""

    def __init__(self, uri: str):
        from rosbags.rosbag2 import StoragePlugin, Writer

        # rosbags creates the directory itself: hand it over empty.
        os.rmdir(uri)
        self.writer = Writer(uri, version=9, storage_plugin=StoragePlugin.SQLITE3)
        self.writer.open()
        self.name = os.path.basename(self.writer.storage.path)
        self.path = str(self.writer.storage.path)

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


# --------------------------------------------------------------------------------------
# Reading
# --------------------------------------------------------------------------------------

def check_bag_path(path: str) -> None:
    if not os.path.exists(path):
        raise BagError(f"Bag '{path}' does not exist")
    if not os.path.isdir(path):
        raise BagError(f"'{path}' is not a bag directory (a rosbag2 bag is a directory "
                       'holding metadata.yaml)')


def read_metadata(path: str) -> BagMetadata:
    check_bag_path(path)
    return read_metadata_file(path)


class BagReader:
    """Messages of a bag in time order, read with `rosbags`; BagError on damaged files."""

    def __init__(self, path: str):
        from rosbags.rosbag2 import Reader

        self.meta = read_metadata(path)
        self.path = path
        try:
            self.reader = Reader(path)
            self.reader.open()
        except Exception as error:  # any library failure is a damaged bag to the user
            raise BagError(f"Cannot open bag '{path}': a storage file is truncated or corrupt "
                           f'({one_line(error)}); an MCAP bag can be salvaged with '
                           f"'ros2 bag reindex {path}'") from None

    def messages(self, topics: set[str] | None = None, start_ns: int = 0,
                 order: str = 'time', end_ns: int | None = None
                 ) -> Iterator[tuple[str, int, bytes]]:
        """(topic, receive stamp, data), file after file, each file in time order.

        `order` 'reverse' goes from the last file's last message back to the first, from
        `end_ns` (inclusive) down; 'file' gives each (MCAP) file's messages as written.
        Each storage file is read with its own topics: rosbags' reader matches them with
        metadata.yaml's by their QoS text too, which older bags (version 4 to 8, integer
        policies) spell differently, and then it finds no message at all.
        """
        directory = self.reader.storage  # rosbags' DirectoryReader: one storage per file
        message_compressed = directory.metadata.compression_mode == 'message'
        storages = directory.storages[::-1] if order == 'reverse' else directory.storages
        stop = None if end_ns is None else end_ns + 1
        try:
            for storage in storages:
                connections = [c for c in storage.connections
                               if topics is None or c.topic in topics]
                if not connections:
                    continue
                if order == 'file':
                    found = storage.messages_scan(connections, start_ns or None, stop)
                elif order == 'reverse':
                    # rosbags reads forwards only: one file at a time is held to turn it.
                    found = reversed(list(storage.messages(connections, start_ns or None,
                                                           stop)))
                else:
                    found = storage.messages(connections, start_ns or None, stop)
                for connection, stamp, data in found:
                    if message_compressed:
                        data = _zstd_decompress(data)
                    yield connection.topic, stamp, bytes(data)
        except Exception as error:
            raise BagError(f"Bag '{self.path}' is damaged: {one_line(error)}; an MCAP bag can "
                           f"be salvaged with 'ros2 bag reindex {self.path}'") from None

    def verify(self) -> None:
        """Read every message once: a truncated or corrupt file fails here."""
        for _ in self.messages():
            pass

    def close(self) -> None:
        try:
            self.reader.close()
        except Exception:  # closing a damaged file may fail again: nothing to add
            pass


# --------------------------------------------------------------------------------------
# Recovery
# --------------------------------------------------------------------------------------

def _storage_files(path: str, suffix: str) -> list[str]:
    return sorted((n for n in os.listdir(path) if n.endswith(suffix)),
                  key=lambda n: (len(n), n))


def reindex(path: str, storage: str = '') -> BagMetadata:
    """Rebuild metadata.yaml of a bag whose recorder died (or that lost it).

    MCAP: reads every `.mcap` file of the directory with the `mcap` library's streaming
    reader, stops at the first damaged record, rewrites the file completely with the `mcap`
    writer and writes metadata.yaml from what was found. SQLite3: counts what each `.db3`
    file's tables hold.
    """
    check_bag_path(path)
    if storage not in ('', *STORAGES):
        raise BagError(f"Unknown storage id '{storage}' (allowed: {', '.join(STORAGES)})")
    if storage == 'sqlite3' or (not storage and not _storage_files(path, '.mcap')
                                and _storage_files(path, '.db3')):
        return _reindex_sqlite3(path)
    names = _storage_files(path, '.mcap')
    if not names:
        raise BagError(f"'{path}' holds no .mcap or .db3 file: nothing to reindex")
    from mcap.stream_reader import StreamReader

    topics: dict[str, TopicInfo] = {}
    counts = []
    for name in names:
        source = os.path.join(path, name)
        salvaged = source + '.reindexed'
        schemas: dict[int, Any] = {}
        channels: dict[int, Any] = {}
        stats = _FileStats(name)
        with open(source, 'rb') as stream, open(salvaged, 'wb') as out:
            from mcap.records import Channel, Message, Schema
            from mcap.writer import CompressionType, Writer

            writer = Writer(out, chunk_size=MCAP_CHUNK_SIZE, compression=CompressionType.NONE)
            writer.start(profile='ros2', library='ros2bag reindex (python mcap)')
            new_schema: dict[int, int] = {}
            new_channel: dict[int, int] = {}
            try:
                for record in StreamReader(stream, skip_magic=False).records:
                    if isinstance(record, Schema) and record.id not in schemas:
                        schemas[record.id] = record
                        new_schema[record.id] = writer.register_schema(
                            record.name, record.encoding, record.data)
                    elif isinstance(record, Channel) and record.id not in channels:
                        channels[record.id] = record
                        new_channel[record.id] = writer.register_channel(
                            record.topic, record.message_encoding,
                            new_schema.get(record.schema_id, 0), dict(record.metadata))
                        topics.setdefault(record.topic, _topic_of(record, schemas))
                    elif isinstance(record, Message) and record.channel_id in new_channel:
                        writer.add_message(new_channel[record.channel_id], record.log_time,
                                           record.data, record.publish_time, record.sequence)
                        stats.add(record.log_time)
                        topics[channels[record.channel_id].topic].message_count += 1
            except Exception:  # the damaged tail is what reindex cuts off
                pass
            meta_stub = BagMetadata('mcap', [name], list(topics.values()))
            writer.add_metadata('rosbag2', {'serialized_metadata': dump_yaml(
                metadata_to_dict(meta_stub))})
            writer.finish()
        os.replace(salvaged, source)
        counts.append(stats)
    return _write_reindexed(path, 'mcap', names, topics, counts)


def _write_reindexed(path: str, storage: str, names: list[str], topics: dict[str, TopicInfo],
                     counts: list[_FileStats]) -> BagMetadata:
    counted = [s for s in counts if s.count]
    start = min((s.start for s in counted), default=0)
    end = max((s.end for s in counted), default=0)
    meta = BagMetadata(
        storage_identifier=storage, relative_file_paths=names, topics=list(topics.values()),
        starting_time_ns=start, duration_ns=end - start,
        message_count=sum(s.count for s in counts),
        file_counts=[(s.path, s.start, s.end - s.start, s.count) for s in counts])
    write_metadata_file(path, meta)
    return meta


def _reindex_sqlite3(path: str) -> BagMetadata:
    import sqlite3

    import yaml

    names = _storage_files(path, '.db3')
    if not names:
        raise BagError(f"'{path}' holds no .db3 file: nothing to reindex")
    topics: dict[str, TopicInfo] = {}
    counts = []
    for name in names:
        stats = _FileStats(name)
        try:
            with sqlite3.connect(f'file:{os.path.join(path, name)}?mode=ro', uri=True) as db:
                columns = [c[1] for c in db.execute('PRAGMA table_info(topics)')]
                hashes = 'type_description_hash' in columns
                rows = db.execute(
                    'SELECT t.name, t.type, t.serialization_format, t.offered_qos_profiles, '
                    + ('t.type_description_hash, ' if hashes else "'', ")
                    + 'COUNT(m.id), MIN(m.timestamp), MAX(m.timestamp) FROM topics t '
                    'LEFT JOIN messages m ON m.topic_id = t.id GROUP BY t.id').fetchall()
        except sqlite3.Error as error:
            raise BagError(f"Cannot reindex '{os.path.join(path, name)}': {error}") from None
        for topic, type_name, fmt, qos, type_hash, count, first, last in rows:
            try:
                profiles = yaml.safe_load(qos) if qos else []
            except yaml.YAMLError:
                profiles = []
            info = topics.setdefault(topic, TopicInfo(
                name=topic, type=type_name, serialization_format=fmt,
                offered_qos_profiles=profiles if isinstance(profiles, list) else [],
                type_description_hash=type_hash or ''))
            info.message_count += count
            if count:
                stats.add(first)
                stats.add(last)
                stats.count += count - 2
        counts.append(stats)
    return _write_reindexed(path, 'sqlite3', names, topics, counts)


def _topic_of(channel: Any, schemas: dict[int, Any]) -> TopicInfo:
    import yaml

    schema = schemas.get(channel.schema_id)
    profiles = channel.metadata.get('offered_qos_profiles', '')
    try:
        loaded = yaml.safe_load(profiles) if profiles else []
    except yaml.YAMLError:
        loaded = []
    return TopicInfo(name=channel.topic, type=schema.name if schema else '',
                     serialization_format=channel.message_encoding,
                     offered_qos_profiles=loaded if isinstance(loaded, list) else [],
                     type_description_hash=channel.metadata.get('topic_type_hash', ''))
