"""Rebuilding a bag whose recorder died (`ros2 bag reindex`, rosbag2_py.Reindexer).

MCAP files are read with the `mcap` streaming reader up to their last whole record and
written again complete; SQLite3 files are counted. Either way metadata.yaml is written anew.
"""

from __future__ import annotations

import os
from typing import Any

from rosbag2_py._bag_files import MCAP_CHUNK_SIZE, STORAGES, FileStats, check_bag_path
from rosbag2_py._metadata_io import (
    BagError,
    BagMetadata,
    TopicInfo,
    dump_yaml,
    metadata_to_dict,
    write_metadata_file,
)


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
        stats = FileStats(name)
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
                     counts: list[FileStats]) -> BagMetadata:
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
        stats = FileStats(name)
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
