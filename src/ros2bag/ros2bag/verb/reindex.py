"""ros2 bag reindex: rebuild metadata.yaml (and the MCAP index) of a bag whose recorder died."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2bag.api import print_error


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from rosbag2_py import get_registered_readers

    parser.add_argument('bag_path', help='Bag to reindex')
    parser.add_argument('-s', '--storage', default='', choices=sorted(get_registered_readers()),
                        help='Storage implementation of bag. By default attempts to detect '
                        'automatically.')
    parser.set_defaults(_main=main)


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rosbag2_py import Info, Reindexer, StorageOptions

    try:
        Reindexer().reindex(StorageOptions(uri=args.bag_path, storage_id=args.storage))
        metadata = Info().read_metadata(args.bag_path, args.storage)
    except RuntimeError as error:
        return print_error(str(error))
    print(f"Reindexed '{args.bag_path}': {metadata.message_count} messages in "
          f'{len(metadata.relative_file_paths)} file(s)', file=context.stdout)
    return 0
