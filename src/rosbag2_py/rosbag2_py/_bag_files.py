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
from rosbag2_py._metadata_io import (
    BagError,
    BagMetadata,
    TopicInfo,
    one_line,
    read_metadata_file,
    write_metadata_file,
)
from rosbag2_py._storage_config import (
    MCAP_DEFAULTS,
    mcap_writer_kwargs,
    mcap_writer_options,
    run_pragmas,
    sqlite3_pragmas,
)
from rosbag2_py._storage_files import McapFile, Sqlite3File

STORAGES = ('mcap', 'sqlite3')
DEFAULT_STORAGE = 'mcap'
COMPRESSION_MODES = ('', 'MESSAGE', 'FILE')
COMPRESSION_FORMATS = ('zstd',)
# Each storage's preset profiles (`--storage-preset-profile`): MCAP's compress its chunks with
# zstd, SQLite3's `resilient` commits every write (rosbag2's presets of the same names).
STORAGE_PRESETS = {'mcap': ('fastwrite', 'zstd_fast', 'zstd_small'), 'sqlite3': ('resilient',)}
FLUSH_PERIOD = 0.5  # seconds: the most a SIGKILLed recorder can lose
MCAP_CHUNK_SIZE = MCAP_DEFAULTS['chunkSize']  # mcap-cpp's default, which Jazzy's plugin keeps


# --------------------------------------------------------------------------------------
# Writing
# --------------------------------------------------------------------------------------

@dataclass
class FileStats:
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
                 compression_mode: str = '', compression_format: str = '', preset: str = '',
                 storage_config: str = ''):
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
        # The storage config file is read before anything is created: a bad one changes nothing.
        self._mcap_options: dict[str, Any] = {}
        self._pragmas: list[str] = []
        if storage == 'mcap':
            self._mcap_options = mcap_writer_kwargs(mcap_writer_options(storage_config, preset))
        else:
            self._pragmas = sqlite3_pragmas(storage_config, 'write')
        # Called with (closed file, opened file) paths at each split and at close (opened '').
        self.on_split: Any = None
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
        self.files: list[FileStats] = []
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
        try:
            self._open_file()
        except BagError:  # e.g. a pragma SQLite refused: leave nothing behind
            import shutil
            shutil.rmtree(uri, ignore_errors=True)
            raise

    # ---- files ----
    def _open_file(self) -> None:
        base = os.path.basename(os.path.normpath(self.uri))
        try:
            if self.storage == 'mcap':
                name = f'{base}_{len(self.files)}.mcap'
                self._backend = McapFile(os.path.join(self.uri, name), self._mcap_options)
            else:
                self._backend = Sqlite3File(self.uri, self._pragmas)
                name = self._backend.name
        except OSError as error:
            raise BagError(f"Cannot write to '{self.uri}': {one_line(error)}") from None
        self.files.append(FileStats(name))
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
        if self.storage != 'mcap':
            raise BagError("Splitting is available with '-s mcap' only here")
        with self._lock:
            closed = self.files[-1]
            self._backend.close(self._metadata())
            if self.compression_mode == 'FILE':
                self._compression().put_file(lambda: self._compress(closed))
            self._open_file()
            self._split_event(closed.path, self.files[-1].path)

    def _split_event(self, closed: str, opened: str) -> None:
        if self.on_split is not None:
            self.on_split(os.path.join(self.uri, closed),
                          os.path.join(self.uri, opened) if opened else '')

    def _compress(self, stats: FileStats) -> None:
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
        self._split_event(self.files[-1].path, '')

def _zstd_decompress(data: bytes) -> bytes:
    import zstandard
    return zstandard.ZstdDecompressor().decompress(bytes(data))


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

    def __init__(self, path: str, storage_config: str = ''):
        """`storage_config`: the storage config file; only SQLite3 reads something from it
        (its `read` pragmas), as Jazzy's plugins."""
        from rosbags.rosbag2 import Reader

        self.meta = read_metadata(path)
        self.path = path
        pragmas = sqlite3_pragmas(storage_config, 'read') \
            if self.meta.storage_identifier == 'sqlite3' else []
        try:
            self.reader = Reader(path)
            self.reader.open()
        except Exception as error:  # any library failure is a damaged bag to the user
            raise BagError(f"Cannot open bag '{path}': a storage file is truncated or corrupt "
                           f'({one_line(error)}); an MCAP bag can be salvaged with '
                           f"'ros2 bag reindex {path}'") from None
        if pragmas:
            import apsw

            for storage in self.reader.storage.storages:
                run_pragmas(storage.dbconn, pragmas, apsw.Error)

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
                # rosbags finds chunked messages through their message indexes: without
                # (the MCAP option noMessageIndex) the file is read as written.
                read = storage.messages_scan if order == 'file' or _unindexed(storage) \
                    else storage.messages
                found = read(connections, start_ns or None, stop)
                if order == 'reverse':
                    # rosbags reads forwards only: one file at a time is held to turn it.
                    found = reversed(list(found))
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


def _unindexed(storage: Any) -> bool:
    """An MCAP file whose chunks have no message index."""
    chunks = getattr(storage, 'chunks', None)
    return bool(chunks) and not any(chunk.message_index_offsets for chunk in chunks)
