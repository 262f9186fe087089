"""ros2 bag reindex: rebuild metadata.yaml (and the MCAP index) of a bag whose recorder died."""

from __future__ import annotations

import argparse

from ros2bag.metadata import BagError
from ros2bag.storage import STORAGES, reindex


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('bag_path', help='Bag to reindex')
    parser.add_argument('-s', '--storage', default='mcap', choices=STORAGES,
                        help='Storage implementation of bag (mcap only here).')
    parser.set_defaults(_main=main)


def main(args: argparse.Namespace) -> int | str:
    if args.storage != 'mcap':
        return '[ERROR] [ros2bag]: reindex rebuilds MCAP bags only here'
    try:
        meta = reindex(args.bag_path)
    except BagError as error:
        return f'[ERROR] [ros2bag]: {error}'
    except OSError as error:
        return f"[ERROR] [ros2bag]: Cannot reindex '{args.bag_path}': {error.strerror}"
    print(f"Reindexed '{args.bag_path}': {meta.message_count} messages in "
          f'{len(meta.relative_file_paths)} file(s)')
    return 0
