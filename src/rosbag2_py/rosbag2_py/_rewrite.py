"""bag_rewrite: input bags copied into output bags chosen by a YAML file (`ros2 bag convert`).

The file holds `output_bags:`, a list of storage options (uri, storage_id,
max_bagfile_size, max_bagfile_duration, storage_preset_profile, storage_config_uri) with the
record options that select topics (`all_topics`/`all`, `topics`, `regex`, `exclude` (a regular
expression), `exclude_topics`) and compress them (`compression_mode`, `compression_format`,
`compression_queue_size`, `compression_threads`). Messages go out in received-time order.
"""

from __future__ import annotations

import re
from typing import Any

from rosbag2_py._storage import StorageOptions, TopicMetadata


def _outputs(path: str) -> list[dict]:
    import yaml

    try:
        with open(path, encoding='utf-8') as stream:
            document = yaml.safe_load(stream)
    except (OSError, yaml.YAMLError) as error:
        raise RuntimeError(f"Cannot read output options '{path}': {error}") from None
    if not isinstance(document, dict) or 'output_bags' not in document:
        raise RuntimeError(f"'{path}' must hold the top level key 'output_bags'")
    bags = document['output_bags']
    if not isinstance(bags, list) or not all(isinstance(b, dict) and 'uri' in b for b in bags):
        raise RuntimeError(f"'output_bags' of '{path}' must be a list of mappings with a uri")
    return bags


def _selects(bag: dict, topic: str) -> bool:
    if bag.get('exclude') and re.search(str(bag['exclude']), topic):
        return False
    if topic in (bag.get('exclude_topics') or []):
        return False
    if bag.get('all') or bag.get('all_topics'):
        return True
    if topic in (bag.get('topics') or []):
        return True
    if bag.get('regex'):
        return bool(re.search(str(bag['regex']), topic))
    return not bag.get('topics')


def rewrite(inputs: list[StorageOptions], output_options_path: str) -> None:
    from rosbag2_py._reader import SequentialReader

    outputs = _outputs(output_options_path)
    readers = []
    for options in inputs:
        reader = SequentialReader()
        reader.open(options)
        readers.append(reader)
    writers: list[tuple[dict, Any, set[str]]] = []
    for bag in outputs:
        writer = _writer(bag)
        try:
            options = StorageOptions(
                uri=str(bag['uri']), storage_id=str(bag.get('storage_id', '')),
                max_bagfile_size=int(bag.get('max_bagfile_size', 0)),
                max_bagfile_duration=int(bag.get('max_bagfile_duration', 0)),
                storage_preset_profile=str(bag.get('storage_preset_profile', '')),
                storage_config_uri=str(bag.get('storage_config_uri', '') or ''))
        except (TypeError, ValueError):
            raise RuntimeError(f"Output bag '{bag['uri']}': max_bagfile_size and "
                               'max_bagfile_duration must be integers') from None
        writer.open(options)
        writers.append((bag, writer, set()))
    topics = {t.name: t for r in readers for t in r.get_all_topics_and_types()}
    for bag, writer, created in writers:
        for name, topic in topics.items():
            if _selects(bag, name):
                writer.create_topic(TopicMetadata(0, topic.name, topic.type,
                                                  topic.serialization_format,
                                                  topic.offered_qos_profiles,
                                                  topic.type_description_hash))
                created.add(name)
    messages = sorted((stamp, index, topic, data) for index, reader in enumerate(readers)
                      for topic, data, stamp in _all(reader))
    for stamp, _index, topic, data in messages:
        for _bag, writer, created in writers:
            if topic in created:
                writer.write(topic, data, stamp)
    for _bag, writer, _created in writers:
        writer.close()


def _writer(bag: dict) -> Any:
    """A SequentialWriter, or a compressing one when the bag names a compression mode."""
    from rosbag2_py._compression_options import CompressionOptions, compression_mode_from_string
    from rosbag2_py._writer import SequentialCompressionWriter, SequentialWriter

    mode = str(bag.get('compression_mode', '') or '')
    if not mode or mode.lower() == 'none':
        return SequentialWriter()
    try:
        return SequentialCompressionWriter(CompressionOptions(
            compression_format=str(bag.get('compression_format', '')),
            compression_mode=compression_mode_from_string(mode),
            # A conversion drops nothing unless told to: queue size 0 by default.
            compression_queue_size=int(bag.get('compression_queue_size', 0)),
            compression_threads=int(bag.get('compression_threads', 0))))
    except (TypeError, ValueError) as error:
        raise RuntimeError(f"Output bag '{bag['uri']}': {error}") from None


def _all(reader: Any) -> list[tuple[str, bytes, int]]:
    found = []
    while reader.has_next():
        found.append(reader.read_next())
    reader.close()
    return found
