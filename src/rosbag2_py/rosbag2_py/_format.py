"""A bag's metadata as text, in Jazzy's layout (rosbag2_py's format_bag_meta_data)."""

from __future__ import annotations

import time

from rosbag2_py._metadata_io import (
    BagMetadata,
    is_service_event_topic,
    service_name,
    service_type,
)

INDENT = 19  # the width of 'Topic information: '


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
