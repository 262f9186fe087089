"""Compression options (upstream's `_compression_options`): zstd per message or per file."""

from __future__ import annotations

import enum


class CompressionMode(enum.IntEnum):
    NONE = 0
    FILE = 1
    MESSAGE = 2


NONE = CompressionMode.NONE
FILE = CompressionMode.FILE
MESSAGE = CompressionMode.MESSAGE


def compression_mode_from_string(text: str) -> CompressionMode:
    try:
        return CompressionMode[text.upper()] if text else CompressionMode.NONE
    except KeyError:
        raise ValueError(f"Unknown compression mode '{text}' (allowed: none, file, "
                         'message)') from None


def compression_mode_to_string(mode: CompressionMode) -> str:
    return CompressionMode(mode).name


class CompressionOptions:
    def __init__(self, compression_format: str = '',
                 compression_mode: CompressionMode = CompressionMode.NONE,
                 compression_queue_size: int = 1, compression_threads: int = 0,
                 compression_threads_priority: int = 0) -> None:
        self.compression_format = compression_format
        self.compression_mode = compression_mode
        self.compression_queue_size = compression_queue_size
        self.compression_threads = compression_threads
        self.compression_threads_priority = compression_threads_priority
