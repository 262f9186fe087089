"""ros2 bag list: the storage, converter and compression plugins this rosbag2_py provides.

Jazzy reads pluginlib's XML files from the ament index; here the plugins are rosbag2_py's
own storages and compressors, described with the names, C++ types and base classes that
Jazzy's plugins register, so scripts that parse the output see the same lines.
"""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

PLUGIN_TYPES = ('storage', 'converter', 'compressor', 'decompressor')
# (name, description, type, base class) per storage id / compression format.
_STORAGE = {
    'mcap': ('rosbag2 storage plugin using the MCAP file format',
             'rosbag2_storage_plugins::MCAPStorage'),
    'sqlite3': ('Plugin to write to SQLite3 databases', 'rosbag2_storage_plugins::SqliteStorage'),
}
_STORAGE_BASE = 'rosbag2_storage::storage_interfaces::ReadWriteInterface'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('plugin_type', choices=PLUGIN_TYPES, help='lists available plugins')
    parser.add_argument('-v', '--verbose', action='store_true',
                        help='output verbose information about the available plugin')
    parser.set_defaults(_main=main)


def plugins(plugin_type: str) -> list[tuple[str, str, str, str]]:
    """(name, description, type, base class) of each plugin of `plugin_type`."""
    from rosbag2_py import get_registered_compressors, get_registered_writers

    if plugin_type == 'storage':
        return [(name, *_STORAGE.get(name, ('', '')), _STORAGE_BASE)
                for name in sorted(get_registered_writers())]
    if plugin_type in ('compressor', 'decompressor'):
        role = plugin_type.capitalize()
        return [(name, f'{name.capitalize()} implementation for rosbag2 {plugin_type}',
                 f'rosbag2_compression_{name}::{name.capitalize()}{role}',
                 f'rosbag2_compression::Base{role}Interface')
                for name in sorted(get_registered_compressors())]
    # CDR is read and written natively: like Jazzy's default install, no converter plugin.
    return []


def main(args: argparse.Namespace, context: VerbContext) -> int:
    if args.verbose:
        print(f'available {args.plugin_type} plugins are:', file=context.stdout)
    for name, description, type_name, base_class in plugins(args.plugin_type):
        if not args.verbose:
            print(name, file=context.stdout)
            continue
        print(f'name: {name}', file=context.stdout)
        print(f'\t{description}', file=context.stdout)
        print(f'\ttype: {type_name}', file=context.stdout)
        print(f'\tbase_class: {base_class}', file=context.stdout)
    return 0
