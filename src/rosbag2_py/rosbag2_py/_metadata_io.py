"""rosbag2's metadata: QoS profiles, `metadata.yaml` (version 9, as Jazzy writes it), topics.

Jazzy emits its YAML with yaml-cpp: block style, sequences indented under their key, empty
strings as `""` and an empty map as `~`. The dumper here reproduces that layout, so a bag
written here reads like one written by Jazzy's `ros2 bag record`.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any

VERSION = 9
ROS_DISTRO = 'jazzy'
SERVICE_EVENT_SUFFIX = '/_service_event'
INFINITE_NS = 2**63 - 1


class BagError(Exception):
    """A bag cannot be written or read: the message is the one line the user sees."""


@dataclass
class TopicInfo:
    """One topic of a bag (rosbag2_storage::TopicMetadata plus its message count)."""

    name: str
    type: str
    serialization_format: str = 'cdr'
    offered_qos_profiles: list[dict] = field(default_factory=list)
    type_description_hash: str = ''
    message_count: int = 0


def is_service_event_topic(name: str, type_name: str) -> bool:
    return (name.endswith(SERVICE_EVENT_SUFFIX) and '/srv/' in type_name
            and type_name.endswith('_Event'))


def event_topic(service: str) -> str:
    """A service's event topic; a name that already is one stays (RecordOptions holds those)."""
    name = service if service.startswith('/') else '/' + service
    name = name.rstrip('/')
    return name if name.endswith(SERVICE_EVENT_SUFFIX) else name + SERVICE_EVENT_SUFFIX


def service_name(event_topic: str) -> str:
    return event_topic[:-len(SERVICE_EVENT_SUFFIX)]


def service_type(event_type: str) -> str:
    return event_type[:-len('_Event')]


# --------------------------------------------------------------------------------------
# QoS profiles <-> rosbag2's YAML mapping
# --------------------------------------------------------------------------------------

def _duration(nanoseconds: int) -> dict:
    return {'sec': nanoseconds // 1_000_000_000, 'nsec': nanoseconds % 1_000_000_000}


def qos_to_dict(profile: Any) -> dict:
    """An rclpy QoSProfile as rosbag2 (version 9) stores it: policies by their rmw names."""
    return {
        'history': profile.history.name.lower(),
        'depth': int(profile.depth),
        'reliability': profile.reliability.name.lower(),
        'durability': profile.durability.name.lower(),
        'deadline': _duration(profile.deadline.nanoseconds),
        'lifespan': _duration(profile.lifespan.nanoseconds),
        'liveliness': profile.liveliness.name.lower(),
        'liveliness_lease_duration': _duration(profile.liveliness_lease_duration.nanoseconds),
        'avoid_ros_namespace_conventions': bool(profile.avoid_ros_namespace_conventions),
    }


def _policy(enum: Any, value: Any) -> Any:
    """A policy from version 9's name or version 8's integer."""
    if isinstance(value, int):
        return enum(value)
    return enum[str(value).upper()]


def _to_duration(value: dict) -> Any:
    from rclpy.duration import Duration

    seconds, nanoseconds = int(value['sec']), int(value['nsec'])
    # Older bags hold each RMW's own "infinite"; anything that large means infinite.
    if seconds >= 0x7FFFFFFF:
        return Duration(nanoseconds=INFINITE_NS)
    return Duration(seconds=seconds, nanoseconds=nanoseconds)


def qos_from_dict(value: dict) -> Any:
    from rclpy.qos import (
        DurabilityPolicy,
        HistoryPolicy,
        LivelinessPolicy,
        QoSProfile,
        ReliabilityPolicy,
    )

    return QoSProfile(
        history=_policy(HistoryPolicy, value['history']),
        depth=int(value.get('depth', 0)),
        reliability=_policy(ReliabilityPolicy, value['reliability']),
        durability=_policy(DurabilityPolicy, value['durability']),
        deadline=_to_duration(value['deadline']),
        lifespan=_to_duration(value['lifespan']),
        liveliness=_policy(LivelinessPolicy, value['liveliness']),
        liveliness_lease_duration=_to_duration(value['liveliness_lease_duration']),
        avoid_ros_namespace_conventions=bool(value.get('avoid_ros_namespace_conventions')),
    )


def request_qos_for_offers(offers: list[Any]) -> Any:
    """The subscription QoS that connects to every offer, as rosbag2's adapt_request_to_offers.

    Reliable only when every publisher is reliable, transient-local only when every publisher
    is; deadline and liveliness left unspecified (always compatible).
    """
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

    reliable = bool(offers) and all(
        p.reliability == ReliabilityPolicy.RELIABLE for p in offers)
    latched = bool(offers) and all(
        p.durability == DurabilityPolicy.TRANSIENT_LOCAL for p in offers)
    # Depth: rosbag2 asks for 10; a Python callback takes a message slower than C++ does, so
    # a deeper queue absorbs bursts (history depth never affects compatibility).
    return QoSProfile(
        depth=1000,
        reliability=ReliabilityPolicy.RELIABLE if reliable or not offers
        else ReliabilityPolicy.BEST_EFFORT,
        durability=DurabilityPolicy.TRANSIENT_LOCAL if latched
        else DurabilityPolicy.VOLATILE)


def offer_qos_for_recorded(profiles: list[dict]) -> Any:
    """The publisher QoS for playback, as rosbag2's adapt_offer_to_recorded_offers."""
    from rclpy.qos import QoSProfile

    if not profiles:
        return QoSProfile(depth=10)
    keys = ('reliability', 'durability', 'deadline', 'liveliness', 'liveliness_lease_duration')
    first = profiles[0]
    if all(all(p.get(k) == first.get(k) for k in keys) for p in profiles[1:]):
        qos = qos_from_dict(first)
        # rosbag2 keeps the compatibility policies and falls back to its default history.
        from rclpy.qos import HistoryPolicy
        qos.history = HistoryPolicy.KEEP_LAST
        qos.depth = 10
        return qos
    return QoSProfile(depth=10)


# --------------------------------------------------------------------------------------
# metadata.yaml
# --------------------------------------------------------------------------------------

@dataclass
class BagMetadata:
    storage_identifier: str
    relative_file_paths: list[str]
    topics: list[TopicInfo]
    starting_time_ns: int = 0
    duration_ns: int = 0
    message_count: int = 0
    file_counts: list[tuple[str, int, int, int]] = field(default_factory=list)
    ros_distro: str = ROS_DISTRO
    version: int = VERSION
    custom_data: dict[str, str] = field(default_factory=dict)
    bag_size: int = 0
    compression_format: str = ''
    compression_mode: str = ''


def metadata_to_dict(meta: BagMetadata) -> dict:
    """The `rosbag2_bagfile_information` mapping, key order as Jazzy's."""
    return {
        'version': meta.version,
        'storage_identifier': meta.storage_identifier,
        'duration': {'nanoseconds': meta.duration_ns},
        'starting_time': {'nanoseconds_since_epoch': meta.starting_time_ns},
        'message_count': meta.message_count,
        'topics_with_message_count': [
            {'topic_metadata': {
                'name': t.name,
                'type': t.type,
                'serialization_format': t.serialization_format,
                'offered_qos_profiles': t.offered_qos_profiles,
                'type_description_hash': t.type_description_hash,
            }, 'message_count': t.message_count} for t in meta.topics],
        'compression_format': meta.compression_format,
        'compression_mode': meta.compression_mode,
        'relative_file_paths': list(meta.relative_file_paths),
        'files': [
            {'path': path, 'starting_time': {'nanoseconds_since_epoch': start},
             'duration': {'nanoseconds': duration}, 'message_count': count}
            for path, start, duration, count in meta.file_counts],
        'custom_data': dict(meta.custom_data) or None,
        'ros_distro': meta.ros_distro,
    }


def _dumper() -> Any:
    import yaml

    class YamlCppDumper(yaml.SafeDumper):
        """PyYAML with yaml-cpp's layout: `- ` items indented under their key."""

        def increase_indent(self, flow: bool = False, indentless: bool = False) -> Any:
            return super().increase_indent(flow, False)

        def ignore_aliases(self, data: Any) -> bool:
            return True  # yaml-cpp repeats shared profiles; no anchors

    def represent_str(dumper: Any, data: str) -> Any:
        style = '"' if data == '' else None
        return dumper.represent_scalar('tag:yaml.org,2002:str', data, style=style)

    def represent_none(dumper: Any, _data: None) -> Any:
        return dumper.represent_scalar('tag:yaml.org,2002:null', '~')

    def represent_dict(dumper: Any, data: dict) -> Any:
        return dumper.represent_mapping('tag:yaml.org,2002:map', data.items())

    YamlCppDumper.add_representer(str, represent_str)
    YamlCppDumper.add_representer(type(None), represent_none)
    YamlCppDumper.add_representer(dict, represent_dict)
    return YamlCppDumper


def dump_yaml(data: Any) -> str:
    import yaml
    return yaml.dump(data, Dumper=_dumper(), default_flow_style=False, sort_keys=False,
                     width=1 << 30, allow_unicode=True)


def dump_qos_profiles(profiles: list[dict]) -> str:
    """The `offered_qos_profiles` string of an MCAP channel (YAML::Dump of the sequence)."""
    return dump_yaml(profiles).rstrip('\n') if profiles else ''


def write_metadata_file(directory: str, meta: BagMetadata) -> None:
    """metadata.yaml, replaced atomically so a reader never sees half of it."""
    text = dump_yaml({'rosbag2_bagfile_information': metadata_to_dict(meta)})
    path = os.path.join(directory, 'metadata.yaml')
    partial = path + '.partial'
    with open(partial, 'w', encoding='utf-8') as stream:
        stream.write(text)
        stream.flush()
        os.fsync(stream.fileno())
    os.replace(partial, path)


def read_metadata_file(directory: str) -> BagMetadata:
    """Parse `<bag>/metadata.yaml` (versions 4 to 9); BagError naming what is wrong."""
    import yaml

    path = os.path.join(directory, 'metadata.yaml')
    try:
        with open(path, encoding='utf-8') as stream:
            document = yaml.safe_load(stream)
    except FileNotFoundError:
        raise BagError(f"No metadata.yaml in '{directory}': not a rosbag2 bag, or its recorder "
                       f"was killed before closing it (try 'ros2 bag reindex {directory}')"
                       ) from None
    except (OSError, yaml.YAMLError) as error:
        raise BagError(f"Cannot read '{path}': {one_line(error)}") from None
    try:
        info = document['rosbag2_bagfile_information']
        version = int(info['version'])
        topics = []
        for entry in info.get('topics_with_message_count') or []:
            topic = entry['topic_metadata']
            profiles = topic.get('offered_qos_profiles') or []
            if isinstance(profiles, str):  # versions 4 to 8: a YAML document in a string
                profiles = yaml.safe_load(profiles) or []
            topics.append(TopicInfo(
                name=str(topic['name']), type=str(topic['type']),
                serialization_format=str(topic.get('serialization_format', 'cdr')),
                offered_qos_profiles=list(profiles),
                type_description_hash=str(topic.get('type_description_hash') or ''),
                message_count=int(entry.get('message_count', 0))))
        files = [(str(f['path']), int(f['starting_time']['nanoseconds_since_epoch']),
                  int(f['duration']['nanoseconds']), int(f['message_count']))
                 for f in info.get('files') or []]
        meta = BagMetadata(
            storage_identifier=str(info['storage_identifier']),
            relative_file_paths=[str(p) for p in info['relative_file_paths']],
            topics=topics,
            starting_time_ns=int(info['starting_time']['nanoseconds_since_epoch']),
            duration_ns=int(info['duration']['nanoseconds']),
            message_count=int(info['message_count']),
            file_counts=files,
            ros_distro=str(info.get('ros_distro') or ''),
            version=version,
            custom_data=dict(info.get('custom_data') or {}),
            compression_format=str(info.get('compression_format') or ''),
            compression_mode=str(info.get('compression_mode') or ''))
    except (KeyError, TypeError, ValueError, AttributeError, yaml.YAMLError) as error:
        raise BagError(f"'{path}' is not valid rosbag2 metadata (missing or bad field "
                       f'{one_line(error)})') from None
    meta.bag_size = directory_size(directory)
    return meta


def directory_size(directory: str) -> int:
    total = 0
    for root, _dirs, files in os.walk(directory):
        for name in files:
            try:
                total += os.path.getsize(os.path.join(root, name))
            except OSError:
                pass
    return total


def one_line(error: BaseException) -> str:
    """An exception as one line for the user: the OS's reason, else its first line."""
    if isinstance(error, OSError) and error.strerror:
        return error.strerror + (f": '{error.filename}'" if error.filename else '')
    text = str(error).strip().splitlines()
    return text[0] if text else type(error).__name__
