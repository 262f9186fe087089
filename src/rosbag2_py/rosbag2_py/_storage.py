"""rosbag2_py's storage structs (upstream's `_storage` module): options, topics, metadata.

Plain Python classes with upstream's constructor keywords and attributes. Times and durations
are rclpy `Time`/`Duration` objects (upstream's pybind11 casters hand those over too).
"""

from __future__ import annotations

import enum
import os
import re
from typing import Any

from rosbag2_py._bag_files import DEFAULT_STORAGE
from rosbag2_py._metadata_io import (
    BagError,
    TopicInfo,
    dump_yaml,
    metadata_to_dict,
    qos_from_dict,
    qos_to_dict,
    read_metadata_file,
    write_metadata_file,
)
from rosbag2_py._metadata_io import BagMetadata as _Meta


def get_default_storage_id() -> str:
    return DEFAULT_STORAGE


class StorageOptions:
    def __init__(self, uri: str, storage_id: str = '', max_bagfile_size: int = 0,
                 max_bagfile_duration: int = 0, max_cache_size: int = 100 * 1024 * 1024,
                 storage_preset_profile: str = '', storage_config_uri: str = '',
                 snapshot_mode: bool = False, start_time_ns: int = -1, end_time_ns: int = -1,
                 custom_data: dict[str, str] | None = None) -> None:
        self.uri = os.fspath(uri)
        self.storage_id = storage_id
        self.max_bagfile_size = max_bagfile_size
        self.max_bagfile_duration = max_bagfile_duration
        self.max_cache_size = max_cache_size
        self.storage_preset_profile = storage_preset_profile
        self.storage_config_uri = storage_config_uri
        self.snapshot_mode = snapshot_mode
        self.start_time_ns = start_time_ns
        self.end_time_ns = end_time_ns
        self.custom_data = dict(custom_data or {})


class ConverterOptions:
    def __init__(self, input_serialization_format: str = '',
                 output_serialization_format: str = '') -> None:
        self.input_serialization_format = input_serialization_format
        self.output_serialization_format = output_serialization_format


class StorageFilter:
    def __init__(self, topics: list[str] | None = None,
                 services_events: list[str] | None = None, regex: str = '',
                 exclude_topics: list[str] | None = None,
                 exclude_service_events: list[str] | None = None,
                 regex_to_exclude: str = '') -> None:
        self.topics = list(topics or [])
        self.services_events = list(services_events or [])
        self.regex = regex
        self.exclude_topics = list(exclude_topics or [])
        self.exclude_service_events = list(exclude_service_events or [])
        self.regex_to_exclude = regex_to_exclude


def filter_selects(rule: StorageFilter, topic: str) -> bool:
    """Whether `rule` lets `topic` through, as Jazzy's storage plugins decide: the lists and
    `regex` select (nothing given: everything), the exclusions win; regular expressions must
    match the whole name (std::regex_match)."""
    if rule.regex_to_exclude and re.fullmatch(rule.regex_to_exclude, topic):
        return False
    if topic in rule.exclude_topics or topic in rule.exclude_service_events:
        return False
    if not (rule.topics or rule.services_events or rule.regex):
        return True
    return topic in rule.topics or topic in rule.services_events or bool(
        rule.regex and re.fullmatch(rule.regex, topic))


class ReadOrderSortBy(enum.IntEnum):
    ReceivedTimestamp = 0
    PublishedTimestamp = 1
    File = 2


class ReadOrder:
    def __init__(self, sort_by: ReadOrderSortBy = ReadOrderSortBy.ReceivedTimestamp,
                 reverse: bool = False) -> None:
        self.sort_by = sort_by
        self.reverse = reverse


def _profiles_as_dicts(profiles: Any) -> list[dict]:
    """Offered QoS profiles given as rclpy QoSProfiles, rosbag2's dicts or its YAML text."""
    if not profiles:
        return []
    if isinstance(profiles, str):
        import yaml
        profiles = yaml.safe_load(profiles) or []
    return [dict(p) if isinstance(p, dict) else qos_to_dict(p) for p in profiles]


class TopicMetadata:
    def __init__(self, id: int = 0, name: str = '', type: str = '',
                 serialization_format: str = 'cdr', offered_qos_profiles: Any = None,
                 type_description_hash: str = '') -> None:
        self.id = id
        self.name = name
        self.type = type
        self.serialization_format = serialization_format
        self.offered_qos_profiles = offered_qos_profiles or []
        self.type_description_hash = type_description_hash

    def equals(self, other: TopicMetadata) -> bool:
        return (self.name, self.type, self.serialization_format) == (
            other.name, other.type, other.serialization_format)

    def __repr__(self) -> str:
        return f'TopicMetadata(name={self.name!r}, type={self.type!r})'

    def _info(self) -> TopicInfo:
        return TopicInfo(name=self.name, type=self.type,
                         serialization_format=self.serialization_format or 'cdr',
                         offered_qos_profiles=_profiles_as_dicts(self.offered_qos_profiles),
                         type_description_hash=self.type_description_hash)

    @classmethod
    def _of(cls, topic: TopicInfo, topic_id: int = 0) -> TopicMetadata:
        return cls(id=topic_id, name=topic.name, type=topic.type,
                   serialization_format=topic.serialization_format,
                   offered_qos_profiles=[qos_from_dict(p) for p in topic.offered_qos_profiles
                                         if _complete(p)],
                   type_description_hash=topic.type_description_hash)


def _complete(profile: dict) -> bool:
    try:
        qos_from_dict(profile)
    except (KeyError, ValueError, TypeError):
        return False
    return True


class TopicInformation:
    def __init__(self, topic_metadata: TopicMetadata, message_count: int = 0) -> None:
        self.topic_metadata = topic_metadata
        self.message_count = message_count


def _time(value: Any) -> Any:
    from rclpy.time import Time
    if isinstance(value, Time):
        return value
    return Time(nanoseconds=int(getattr(value, 'nanoseconds', value or 0)))


def _duration(value: Any) -> Any:
    from rclpy.duration import Duration
    if isinstance(value, Duration):
        return value
    if hasattr(value, 'total_seconds'):  # datetime.timedelta
        return Duration(nanoseconds=int(value.total_seconds() * 1e9))
    return Duration(nanoseconds=int(getattr(value, 'nanoseconds', value or 0)))


class FileInformation:
    def __init__(self, path: str, starting_time: Any = 0, duration: Any = 0,
                 message_count: int = 0) -> None:
        self.path = path
        self.starting_time = _time(starting_time)
        self.duration = _duration(duration)
        self.message_count = message_count


class MessageDefinition:
    def __init__(self, topic_type: str, encoding: str, encoded_message_definition: str,
                 type_hash: str = '') -> None:
        self.topic_type = topic_type
        self.encoding = encoding
        self.encoded_message_definition = encoded_message_definition
        self.type_hash = type_hash


class BagMetadata:
    def __init__(self, version: int = 9, bag_size: int = 0, storage_identifier: str = '',
                 relative_file_paths: list[str] | None = None,
                 files: list[FileInformation] | None = None, duration: Any = 0,
                 starting_time: Any = 0, message_count: int = 0,
                 topics_with_message_count: list[TopicInformation] | None = None,
                 compression_format: str = '', compression_mode: str = '',
                 custom_data: dict[str, str] | None = None, ros_distro: str = '') -> None:
        self.version = version
        self.bag_size = bag_size
        self.storage_identifier = storage_identifier
        self.relative_file_paths = list(relative_file_paths or [])
        self.files = list(files or [])
        self.duration = _duration(duration)
        self.starting_time = _time(starting_time)
        self.message_count = message_count
        self.topics_with_message_count = list(topics_with_message_count or [])
        self.compression_format = compression_format
        self.compression_mode = compression_mode
        self.custom_data = dict(custom_data or {})
        self.ros_distro = ros_distro

    def __str__(self) -> str:
        """As `ros2 bag info` prints it (upstream's format_bag_meta_data)."""
        from rosbag2_py._format import format_metadata
        return format_metadata(self._meta())

    @classmethod
    def _of(cls, meta: _Meta) -> BagMetadata:
        return cls(
            version=meta.version, bag_size=meta.bag_size,
            storage_identifier=meta.storage_identifier,
            relative_file_paths=meta.relative_file_paths,
            files=[FileInformation(path, start, duration, count)
                   for path, start, duration, count in meta.file_counts],
            duration=meta.duration_ns, starting_time=meta.starting_time_ns,
            message_count=meta.message_count,
            topics_with_message_count=[
                TopicInformation(TopicMetadata._of(t, i + 1), t.message_count)
                for i, t in enumerate(meta.topics)],
            compression_format=meta.compression_format,
            compression_mode=meta.compression_mode, custom_data=meta.custom_data,
            ros_distro=meta.ros_distro)

    def _meta(self) -> _Meta:
        topics = []
        for information in self.topics_with_message_count:
            topic = information.topic_metadata._info()
            topic.message_count = information.message_count
            topics.append(topic)
        return _Meta(
            storage_identifier=self.storage_identifier,
            relative_file_paths=self.relative_file_paths, topics=topics,
            starting_time_ns=self.starting_time.nanoseconds,
            duration_ns=self.duration.nanoseconds, message_count=self.message_count,
            file_counts=[(f.path, f.starting_time.nanoseconds, f.duration.nanoseconds,
                          f.message_count) for f in self.files],
            ros_distro=self.ros_distro, version=self.version, custom_data=self.custom_data,
            bag_size=self.bag_size, compression_format=self.compression_format,
            compression_mode=self.compression_mode)


class MetadataIo:
    """metadata.yaml of a bag directory, read and written."""

    def metadata_file_exists(self, uri: str) -> bool:
        return os.path.isfile(os.path.join(uri, 'metadata.yaml'))

    def read_metadata(self, uri: str) -> BagMetadata:
        try:
            return BagMetadata._of(read_metadata_file(uri))
        except BagError as error:
            raise RuntimeError(str(error)) from None

    def write_metadata(self, uri: str, metadata: BagMetadata) -> None:
        write_metadata_file(uri, metadata._meta())

    def serialize_metadata(self, metadata: BagMetadata) -> str:
        return dump_yaml({'rosbag2_bagfile_information': metadata_to_dict(metadata._meta())})

    def deserialize_metadata(self, text: str) -> BagMetadata:
        import tempfile
        with tempfile.TemporaryDirectory() as directory:
            with open(os.path.join(directory, 'metadata.yaml'), 'w', encoding='utf-8') as out:
                out.write(text)
            return self.read_metadata(directory)


def convert_rclcpp_qos_to_rclpy_qos(profile: Any) -> Any:
    """Upstream converts its C++ QoS; here offered profiles already are rclpy QoSProfiles."""
    return profile


def to_rclcpp_qos_vector(text: str, version: int = 9) -> list:
    """The offered QoS profiles of a metadata YAML string, as rclpy QoSProfiles."""
    return [qos_from_dict(p) for p in _profiles_as_dicts(text)]
