"""ros2 bag convert: write input bags out again as the bags an options file describes
(rosbag2_py.bag_rewrite: other storage, compression, a subset of topics, merged bags)."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2bag.api import print_error


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-i', '--input', required=True, action='append', nargs='+',
                        metavar=('uri', 'storage_id'),
                        help='URI (and optional storage ID) of an input bag. May be provided '
                        'more than once')
    parser.add_argument('-o', '--output-options', type=str, required=True,
                        help='YAML file with options for output bags. Must have one top-level '
                        'key "output_bags", which contains a sequence of '
                        'StorageOptions/RecordOptions objects.')
    parser.set_defaults(_main=main)


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rosbag2_py import StorageOptions, bag_rewrite

    inputs = []
    for given in args.input:
        if len(given) > 2:
            return print_error(f'--input expects 1 or 2 arguments (uri [storage_id]), '
                               f'{len(given)} provided')
        inputs.append(StorageOptions(uri=given[0], storage_id=given[1] if len(given) > 1
                                     else ''))
    try:
        bag_rewrite(inputs, args.output_options)
    except RuntimeError as error:
        return print_error(str(error))
    return 0
