"""rosbag2_py: Jazzy's Python API for rosbag2 bags (MCAP and SQLite3), in Python.

Bags are written with the `mcap` and `rosbags` libraries and read with `rosbags`; the same
code serves `ros2 bag` (package ros2bag), so a bag of one is a bag of the other.
"""

from rosbag2_py._bag_files import STORAGE_PRESETS
from rosbag2_py._compression_options import (
    CompressionMode,
    CompressionOptions,
    compression_mode_from_string,
    compression_mode_to_string,
)
from rosbag2_py._info import Info
from rosbag2_py._message_definitions import LocalMessageDefinitionSource
from rosbag2_py._reader import (
    SequentialCompressionReader,
    SequentialReader,
    get_registered_readers,
)
from rosbag2_py._reindexer import Reindexer
from rosbag2_py._storage import (
    BagMetadata,
    ConverterOptions,
    FileInformation,
    MessageDefinition,
    MetadataIo,
    ReadOrder,
    ReadOrderSortBy,
    StorageFilter,
    StorageOptions,
    TopicInformation,
    TopicMetadata,
    convert_rclcpp_qos_to_rclpy_qos,
    get_default_storage_id,
    to_rclcpp_qos_vector,
)
from rosbag2_py._transport import (
    Player,
    PlayOptions,
    Recorder,
    RecordOptions,
    ServiceRequestsSource,
    bag_rewrite,
)
from rosbag2_py._writer import (
    SequentialCompressionWriter,
    SequentialWriter,
    get_registered_compressors,
    get_registered_serializers,
    get_registered_writers,
)

__all__ = [
    'STORAGE_PRESETS',
    'BagMetadata',
    'CompressionMode',
    'CompressionOptions',
    'ConverterOptions',
    'FileInformation',
    'Info',
    'LocalMessageDefinitionSource',
    'MessageDefinition',
    'MetadataIo',
    'PlayOptions',
    'Player',
    'ReadOrder',
    'ReadOrderSortBy',
    'RecordOptions',
    'Recorder',
    'Reindexer',
    'SequentialCompressionReader',
    'SequentialCompressionWriter',
    'SequentialReader',
    'SequentialWriter',
    'ServiceRequestsSource',
    'StorageFilter',
    'StorageOptions',
    'TopicInformation',
    'TopicMetadata',
    'bag_rewrite',
    'compression_mode_from_string',
    'compression_mode_to_string',
    'convert_rclcpp_qos_to_rclpy_qos',
    'get_default_storage_id',
    'get_registered_compressors',
    'get_registered_readers',
    'get_registered_serializers',
    'get_registered_writers',
    'to_rclcpp_qos_vector',
]
