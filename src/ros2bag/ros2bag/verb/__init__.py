"""What the writing verbs share: the storage choice and its preset profiles."""

from __future__ import annotations

import argparse


def add_storage_preset_arguments(parser: argparse.ArgumentParser, default: str) -> None:
    """`-s/--storage` and `--storage-preset-profile`, whose help lists each storage's presets
    (upstream's storage plugins add theirs: `zstd_small` for MCAP, `resilient` for SQLite3)."""
    from rosbag2_py import STORAGE_PRESETS, get_registered_writers

    parser.add_argument('-s', '--storage', default=default,
                        choices=sorted(get_registered_writers()),
                        help=f"Storage identifier to be used, defaults to '{default}'.")
    lines = [f'{storage}: {", ".join(presets)}' for storage, presets in STORAGE_PRESETS.items()]
    parser.add_argument(
        '--storage-preset-profile', type=str, default='',
        help='Select a configuration preset for storage.\n' + '\n'.join(lines))
    parser.add_argument(
        '--storage-config-file', type=argparse.FileType('r'),
        help='Path to a yaml file defining storage specific configurations. See the storage '
        'plugin documentation for the format of this file (MCAP: writer options such as '
        'compression, chunkSize; SQLite3: write/read pragmas).')
