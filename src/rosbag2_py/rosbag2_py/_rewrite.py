"""bag_rewrite: input bags copied into output bags chosen by a YAML file (`ros2 bag convert`).

The file holds `output_bags:`, a list of storage options (uri, storage_id, ...) with the
record options that select topics: `all_topics`/`all`, `topics`, `regex`, `exclude`
(a regular expression) and `exclude_topics`. Messages go out in received-time order.
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
    from rosbag2_py._writer import SequentialWriter

    outputs = _outputs(output_options_path)
    readers = []
    for options in inputs:
        reader = SequentialReader()
        reader.open(options)
        readers.append(reader)
    writers: list[tuple[dict, Any, set[str]]] = []
    for bag in outputs:
        writer = SequentialWriter()
        writer.open(StorageOptions(uri=str(bag['uri']), storage_id=str(bag.get('storage_id', ''))))
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


def _all(reader: Any) -> list[tuple[str, bytes, int]]:
    found = []
    while reader.has_next():
        found.append(reader.read_next())
    reader.close()
    return found
