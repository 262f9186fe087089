"""SequentialReader: a bag's messages in order, file after file (one implementation with
`ros2 bag play`/`info`, see _bag_files.BagReader).

A filter or a seek takes effect from where the reader stands, as upstream's: set_filter and
reset_filter go on from the current position, seek keeps the filter.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from rosbag2_py._bag_files import STORAGES, BagReader
from rosbag2_py._definitions import full_text
from rosbag2_py._metadata_io import BagError
from rosbag2_py._storage import (
    BagMetadata,
    ConverterOptions,
    MessageDefinition,
    ReadOrder,
    ReadOrderSortBy,
    StorageFilter,
    StorageOptions,
    TopicMetadata,
    filter_selects,
)

_ENCODINGS = {'MSG': 'ros2msg', 'IDL': 'ros2idl'}


def get_registered_readers() -> set[str]:
    return set(STORAGES)


class SequentialReader:
    def __init__(self) -> None:
        self._bag: BagReader | None = None
        self._filter = StorageFilter()
        self._messages: Iterator[tuple[str, int, bytes]] | None = None
        self._next: tuple[str, int, bytes] | None = None
        self._order = ReadOrder()
        self._seek: int | None = None  # where seek() put the reader (None: the bag's edge)

    def open(self, storage_options: StorageOptions,
             converter_options: ConverterOptions | None = None) -> None:
        storage_id = storage_options.storage_id
        if storage_id and storage_id not in STORAGES:
            raise RuntimeError(f"Unknown storage id '{storage_id}' (allowed: "
                               f"{', '.join(STORAGES)})")
        self.open_uri(storage_options.uri, storage_options.storage_config_uri)

    def open_uri(self, uri: str, storage_config_uri: str = '') -> None:
        self.close()
        try:
            self._bag = BagReader(uri, storage_config_uri)
        except BagError as error:
            raise RuntimeError(str(error)) from None
        self._order = ReadOrder()
        self._seek = None
        self._restart()

    def _reader(self) -> BagReader:
        if self._bag is None:
            raise RuntimeError('Bag is not open. Call open() before reading.')
        return self._bag

    def close(self) -> None:
        if self._bag is not None:
            self._bag.close()
            self._bag = None

    # ---- what the bag holds ----
    def get_metadata(self) -> BagMetadata:
        return BagMetadata._of(self._reader().meta)

    def get_all_topics_and_types(self) -> list[TopicMetadata]:
        return [TopicMetadata._of(topic, index + 1)
                for index, topic in enumerate(self._reader().meta.topics)]

    def get_all_message_definitions(self) -> list[MessageDefinition]:
        """Each type's definition as the bag stores it (else from the installed files)."""
        found: dict[str, MessageDefinition] = {}
        for connection in self._reader().reader.connections:
            if connection.msgtype in found:
                continue
            definition = connection.msgdef
            text = definition.data if definition else ''
            encoding = _ENCODINGS.get(definition.format.name, '') if definition else ''
            if not text:
                encoding, text = full_text(connection.msgtype)
            found[connection.msgtype] = MessageDefinition(
                connection.msgtype, encoding or 'unknown', text, connection.digest or '')
        return list(found.values())

    # ---- reading ----
    def set_filter(self, storage_filter: StorageFilter) -> None:
        for pattern in (storage_filter.regex, storage_filter.regex_to_exclude):
            try:
                re.compile(pattern)
            except re.error as error:
                raise RuntimeError(f"'{pattern}' is not a valid regular expression ({error})"
                                   ) from None
        self._filter = storage_filter
        if self._next is not None and not self._passes(self._next[0]):
            self._next = None

    def reset_filter(self) -> None:
        self.set_filter(StorageFilter())

    def set_read_order(self, read_order: ReadOrder) -> bool:
        """Read on in `read_order` from the seek point (else the bag's start, or its end when
        reversed); False, order unchanged, for an order the bag's storage cannot give (as
        Jazzy's plugins: published-time order nowhere, file order in MCAP forwards only)."""
        bag = self._reader()
        sort_by = int(read_order.sort_by)
        if sort_by == ReadOrderSortBy.PublishedTimestamp or (
                sort_by == ReadOrderSortBy.File and (
                    read_order.reverse or bag.meta.storage_identifier != 'mcap')):
            return False
        self._order = ReadOrder(ReadOrderSortBy(sort_by), bool(read_order.reverse))
        self._restart()
        return True

    def seek(self, timestamp: int) -> None:
        """Go on from the first message at or after `timestamp` (ns); reading in reverse,
        from the last one at or before it."""
        self._reader()
        self._seek = max(0, int(timestamp))
        self._restart()

    def _restart(self) -> None:
        bag = self._reader()
        if self._order.reverse:
            self._messages = bag.messages(order='reverse', end_ns=self._seek)
        else:
            order = 'file' if self._order.sort_by == ReadOrderSortBy.File else 'time'
            self._messages = bag.messages(start_ns=self._seek or 0, order=order)
        self._next = None

    def _passes(self, topic: str) -> bool:
        return filter_selects(self._filter, topic)

    def has_next(self) -> bool:
        if self._next is not None:
            return True
        if self._messages is None:
            self._reader()
            return False
        try:
            for message in self._messages:
                if self._passes(message[0]):
                    self._next = message
                    return True
        except BagError as error:
            raise RuntimeError(str(error)) from None
        self._messages = iter(())
        return False

    def read_next(self) -> tuple[str, bytes, int]:
        """(topic, serialized data, receive time stamp in ns) of the next message."""
        if not self.has_next():
            raise RuntimeError('Bag is at end. No next message.')
        assert self._next is not None
        topic, stamp, data = self._next
        self._next = None
        return topic, data, stamp


class SequentialCompressionReader(SequentialReader):
    """Compressed bags are read by SequentialReader already (the metadata says how)."""
