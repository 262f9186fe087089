"""ros2 bag info: a bag's metadata in Jazzy's layout (rosbag2_py's format_bag_meta_data).

Unlike Jazzy, which reads metadata.yaml only, the storage files are opened too, so a
truncated or corrupt file is reported here rather than half-way through `play`.
"""

from __future__ import annotations

import argparse
import time

from ros2bag.metadata import (
    BagError,
    BagMetadata,
    is_service_event_topic,
    service_name,
    service_type,
)
from ros2bag.storage import STORAGES, BagReader

INDENT = 19  # the width of 'Topic information: '


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('bag_path', help='Bag to open.')
    parser.add_argument('-s', '--storage', default='', choices=STORAGES,
                        help='Storage implementation of bag. By default attempts to detect '
                        'automatically.')
    parser.add_argument('-t', '--topic-name', action='store_true',
                        help='Only display topic names.')
    parser.add_argument('-v', '--verbose', action='store_true',
                        help='Display request/response information for services')
    parser.set_defaults(_main=main)


def main(args: argparse.Namespace) -> int | str:
    try:
        reader = BagReader(args.bag_path)
    except BagError as error:
        return f'[ERROR] [ros2bag]: {error}'
    reader.close()
    meta = reader.meta
    if args.topic_name and not args.verbose:
        for topic in meta.topics:
            if not is_service_event_topic(topic.name, topic.type):
                print(topic.name)
        return 0
    print(format_metadata(meta))
    return 0


def _seconds(nanoseconds: int) -> str:
    return f'{nanoseconds // 1_000_000_000}.{nanoseconds % 1_000_000_000:09d}'


def _time_point(nanoseconds: int) -> str:
    local = time.localtime(nanoseconds // 1_000_000_000)
    date = time.strftime('%b ', local) + f'{local.tm_mday:2d}' + time.strftime(' %Y', local)
    clock = time.strftime('%H:%M:%S', local) + f'.{nanoseconds % 1_000_000_000:09d}'
    return f'{date} {clock} ({_seconds(nanoseconds)})'


def _size(size_bytes: int) -> str:
    size = float(size_bytes)
    units = ['B', 'KiB', 'MiB', 'GiB', 'TiB']
    index = 0
    while size >= 1024 and index < 4:
        size /= 1024
        index += 1
    return f'{size:.0f} {units[index]}' if index == 0 else f'{size:.1f} {units[index]}'


def format_metadata(meta: BagMetadata) -> str:
    pad = ' ' * INDENT
    topics = [t for t in meta.topics if not is_service_event_topic(t.name, t.type)]
    services = [t for t in meta.topics if is_service_event_topic(t.name, t.type)]
    service_events = sum(t.message_count for t in services)
    lines = ['', 'Files:             ' + ('\n' + pad).join(meta.relative_file_paths),
             f'Bag size:          {_size(meta.bag_size)}',
             f'Storage id:        {meta.storage_identifier}',
             f'ROS Distro:        {meta.ros_distro or "unknown"}',
             f'Duration:          {_seconds(meta.duration_ns)}s',
             f'Start:             {_time_point(meta.starting_time_ns)}',
             f'End:               {_time_point(meta.starting_time_ns + meta.duration_ns)}',
             f'Messages:          {meta.message_count - service_events}']
    topic_lines = [f'Topic: {t.name} | Type: {t.type} | Count: {t.message_count} | '
                   f'Serialization Format: {t.serialization_format}' for t in topics]
    lines.append('Topic information: ' + ('\n' + pad).join(topic_lines))
    lines.append(f'Service:           {len(services)}')
    service_lines = [f'Service: {service_name(t.name)} | Type: {service_type(t.type)} | '
                     f'Event Count: {t.message_count} | Serialization Format: '
                     f'{t.serialization_format}' for t in services]
    text = '\n'.join(lines) + '\nService information: '
    if service_lines:
        text += ('\n' + pad + '  ').join(service_lines) + '\n'
    return text
