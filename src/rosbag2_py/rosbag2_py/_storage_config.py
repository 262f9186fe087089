"""`--storage-config-file` (StorageOptions.storage_config_uri), read as Jazzy's plugins read it.

MCAP (rosbag2_storage_mcap's README, "Writer Configuration"): a YAML mapping of
mcap::McapWriterOptions fields, laid over the preset profile, which is laid over rosbag2's
defaults (chunk CRCs off, no compression, 768 KiB chunks). Only the writer reads it.
SQLite3 (rosbag2_storage_sqlite3's README): `write: {pragmas: [...]}` for recording,
`read: {pragmas: [...]}` for playing, each entry a `PRAGMA` statement without the keyword.

Unlike Jazzy, which ignores keys it does not know and fails on a bad value with yaml-cpp's
"bad conversion", every problem is one line naming the file, the key and what is allowed.
"""

from __future__ import annotations

from typing import Any

from rosbag2_py._metadata_io import BagError, one_line

MCAP_FLAGS = ('noChunkCRC', 'noAttachmentCRC', 'enableDataCRC', 'noSummaryCRC', 'noChunking',
              'noMessageIndex', 'noSummary', 'forceCompression', 'noRepeatedSchemas',
              'noRepeatedChannels', 'noAttachmentIndex', 'noMetadataIndex', 'noChunkIndex',
              'noStatistics', 'noSummaryOffsets')
MCAP_COMPRESSIONS = ('None', 'Lz4', 'Zstd')
MCAP_LEVELS = ('Fastest', 'Fast', 'Default', 'Slow', 'Slowest')
MCAP_KEYS = (*MCAP_FLAGS, 'chunkSize', 'compression', 'compressionLevel')
# rosbag2's MCAP writer defaults (mcap_storage.cpp) and its preset profiles.
MCAP_DEFAULTS: dict[str, Any] = {**{flag: False for flag in MCAP_FLAGS}, 'noChunkCRC': True,
                                 'chunkSize': 768 * 1024, 'compression': 'None',
                                 'compressionLevel': 'Default'}
MCAP_PRESETS: dict[str, dict[str, Any]] = {
    'fastwrite': {'noChunking': True, 'noSummaryCRC': True},
    'zstd_fast': {'compression': 'Zstd', 'compressionLevel': 'Fastest', 'noChunkCRC': True},
    'zstd_small': {'compression': 'Zstd', 'compressionLevel': 'Slowest',
                   'chunkSize': 4 * 1024 * 1024},
}
SQLITE3_SECTIONS = ('read', 'write')
PRAGMA_FORBIDDEN = '\';"'  # rosbag2's guard against injected statements


def _load(path: str) -> Any:
    import yaml

    try:
        with open(path, encoding='utf-8') as stream:
            return yaml.safe_load(stream)
    except OSError as error:
        raise BagError(f"Cannot read storage config file '{path}': "
                       f'{error.strerror or error}') from None
    except yaml.YAMLError as error:
        mark = getattr(error, 'problem_mark', None)
        where = f' (line {mark.line + 1})' if mark else ''
        raise BagError(f"Storage config file '{path}' is not valid YAML{where}") from None


def _mapping(document: Any, path: str, what: str) -> dict:
    if document is None:
        return {}
    if not isinstance(document, dict):
        raise BagError(f"Storage config file '{path}' must hold a mapping of {what}, got "
                       f'{type(document).__name__}')
    return document


def mcap_writer_options(path: str, preset: str = '') -> dict[str, Any]:
    """The McapWriterOptions fields for writing: defaults, then the preset, then the file."""
    options = dict(MCAP_DEFAULTS)
    options.update(MCAP_PRESETS.get(preset, {}))
    if not path:
        return options
    for key, value in _mapping(_load(path), path, 'MCAP writer options').items():
        options[key] = _mcap_value(path, key, value)
    return options


def _mcap_value(path: str, key: Any, value: Any) -> Any:
    where = f"Storage config file '{path}': "
    if key in MCAP_FLAGS:
        if not isinstance(value, bool):
            raise BagError(f"{where}'{key}' must be true or false, got {value!r}")
        if key == 'noRepeatedChannels' and value:
            # rosbags then finds no channel, hence no message: the bag could not be read here.
            raise BagError(f"{where}'noRepeatedChannels: true' is not available here (the "
                           "bag's reader, rosbags, needs the channels in the summary)")
        return value
    if key == 'chunkSize':
        if not isinstance(value, int) or isinstance(value, bool) or value < 0:
            raise BagError(f"{where}'chunkSize' must be a non-negative integer (bytes), got "
                           f'{value!r}')
        return value
    for name, allowed in (('compression', MCAP_COMPRESSIONS),
                          ('compressionLevel', MCAP_LEVELS)):
        if key == name:
            if value not in allowed:
                raise BagError(f"{where}'{key}' must be one of {', '.join(allowed)}, got "
                               f'{value!r}')
            return value
    raise BagError(f"{where}unknown MCAP writer option '{key}' (allowed: "
                   f"{', '.join(MCAP_KEYS)})")


def mcap_writer_kwargs(options: dict[str, Any]) -> dict[str, Any]:
    """Keyword arguments of `mcap.writer.Writer` for McapWriterOptions fields.

    The Python writer has one switch for chunk and summary CRCs (both are written unless both
    are turned off), compresses every chunk it is asked to (forceCompression), at the
    compressor's default level, and writes no attachments (noAttachmentCRC has nothing to do).
    """
    from mcap.writer import CompressionType, IndexType

    indexes = IndexType.ALL
    for flag, index in (('noMessageIndex', IndexType.MESSAGE), ('noChunkIndex', IndexType.CHUNK),
                        ('noMetadataIndex', IndexType.METADATA),
                        ('noAttachmentIndex', IndexType.ATTACHMENT)):
        if options[flag]:
            indexes &= ~index
    summary = not options['noSummary']
    return {
        'chunk_size': options['chunkSize'],
        'compression': CompressionType[options['compression'].upper()],
        'index_types': indexes if summary else IndexType.NONE,
        'repeat_channels': summary and not options['noRepeatedChannels'],
        'repeat_schemas': summary and not options['noRepeatedSchemas'],
        'use_chunking': not options['noChunking'],
        'use_statistics': summary and not options['noStatistics'],
        'use_summary_offsets': summary and not options['noSummaryOffsets'],
        'enable_crcs': not (options['noChunkCRC'] and options['noSummaryCRC']),
        'enable_data_crcs': options['enableDataCRC'],
    }


def sqlite3_pragmas(path: str, section: str) -> list[str]:
    """The `PRAGMA ...` statements of the file's `read` or `write` section ([] without one)."""
    if not path:
        return []
    document = _mapping(_load(path), path, "'read' and 'write' sections")
    where = f"Storage config file '{path}': "
    for key in document:
        if key not in SQLITE3_SECTIONS:
            raise BagError(f"{where}unknown SQLite3 section '{key}' (allowed: read, write)")
    settings = document.get(section)
    if settings is None:
        return []
    if not isinstance(settings, dict) or set(settings) - {'pragmas'}:
        raise BagError(f"{where}'{section}' must hold only 'pragmas', a list of SQLite "
                       'pragma settings')
    entries = settings.get('pragmas') or []
    if not isinstance(entries, list) or not all(isinstance(e, str) for e in entries):
        raise BagError(f"{where}'{section}.pragmas' must be a list of strings such as "
                       "'journal_mode = MEMORY'")
    statements = []
    for entry in entries:
        bad = next((c for c in entry if c in PRAGMA_FORBIDDEN), None)
        if bad:
            raise BagError(f"{where}'{section}.pragmas' entry {entry!r} holds {bad!r}; avoid "
                           f'the characters {PRAGMA_FORBIDDEN}')
        if entry.strip()[:1] in ('=', '('):
            raise BagError(f"{where}'{section}.pragmas': incorrect storage setting syntax: "
                           f'{entry!r} (expected NAME, NAME = VALUE or NAME(VALUE))')
        if entry.strip():
            statements.append(f'PRAGMA {entry.strip()};')
    return statements


def run_pragmas(connection: Any, pragmas: list[str], error_type: Any) -> None:
    """Run a storage config file's pragma statements on an SQLite3 connection."""
    for statement in pragmas:
        try:
            connection.execute(statement)
        except error_type as error:
            raise BagError(f"SQLite3 storage config: '{statement}' failed: "
                           f'{one_line(error)}') from None

