"""ros2 bag info: a bag's metadata in Jazzy's layout (rosbag2_py's format_bag_meta_data).

Unlike Jazzy, which reads metadata.yaml only, the storage files are read too, so a truncated
or corrupt file is reported here rather than half-way through `play`.
"""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2bag.api import print_error


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from rosbag2_py import get_registered_readers

    parser.add_argument('bag_path', help='Bag to open.')
    parser.add_argument('-s', '--storage', default='', choices=sorted(get_registered_readers()),
                        help='Storage implementation of bag. By default attempts to detect '
                        'automatically.')
    parser.add_argument('-t', '--topic-name', action='store_true',
                        help='Only display topic names.')
    parser.add_argument('-v', '--verbose', action='store_true',
                        help='Display request/response information for services')
    parser.set_defaults(_main=main)


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rosbag2_py import Info, SequentialReader, StorageOptions

    try:
        metadata = Info().read_metadata(args.bag_path, args.storage)
        reader = SequentialReader()
        reader.open(StorageOptions(uri=args.bag_path, storage_id=args.storage))
        while reader.has_next():
            reader.read_next()
        reader.close()
    except RuntimeError as error:
        return print_error(str(error))
    if args.topic_name and not args.verbose:
        for information in metadata.topics_with_message_count:
            topic = information.topic_metadata
            if not (topic.name.endswith('/_service_event') and '/srv/' in topic.type):
                print(topic.name, file=context.stdout)
        return 0
    print(metadata, file=context.stdout)
    return 0
