"""Info: a bag's metadata (upstream's `_info`), as `ros2 bag info` reads it."""

from __future__ import annotations

from rosbag2_py._bag_files import STORAGES, read_metadata
from rosbag2_py._metadata_io import BagError
from rosbag2_py._storage import BagMetadata


class Info:
    def read_metadata(self, uri: str, storage_id: str = '') -> BagMetadata:
        if storage_id and storage_id not in STORAGES:
            raise RuntimeError(f"Unknown storage id '{storage_id}' (allowed: "
                               f"{', '.join(STORAGES)})")
        try:
            return BagMetadata._of(read_metadata(uri))
        except BagError as error:
            raise RuntimeError(str(error)) from None

    def read_metadata_and_output_service_verbose(self, uri: str, storage_id: str = '') -> None:
        from rosbag2_py._format import format_metadata
        try:
            print(format_metadata(read_metadata(uri)))
        except BagError as error:
            raise RuntimeError(str(error)) from None
