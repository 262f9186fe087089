"""Reindexer: metadata.yaml rebuilt from a bag's storage files (upstream's `_reindexer`)."""

from __future__ import annotations

from rosbag2_py._bag_reindex import reindex
from rosbag2_py._metadata_io import BagError
from rosbag2_py._storage import StorageOptions


class Reindexer:
    def reindex(self, storage_options: StorageOptions) -> None:
        try:
            reindex(storage_options.uri, storage_options.storage_id)
        except BagError as error:
            raise RuntimeError(str(error)) from None
