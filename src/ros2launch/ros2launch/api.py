"""Finding, describing and running launch files for `ros2 launch`."""

from __future__ import annotations

import os

from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import (
    AnyLaunchDescriptionSource,
    get_launch_description_from_any_launch_file,
)

import launch


class MultipleLaunchFilesError(Exception):
    pass


def get_share_file_path_from_package(*, package_name: str, file_name: str) -> str:
    """The one file called `file_name` under the package's share directory."""
    from ament_index_python.packages import get_package_share_directory
    share = get_package_share_directory(package_name)
    matches = [os.path.join(root, name) for root, _, files in os.walk(share)
               for name in files if name == file_name]
    if not matches:
        raise FileNotFoundError(f"file '{file_name}' was not found in the share directory of "
                                f"package '{package_name}' which is at '{share}'")
    if len(matches) > 1:
        raise MultipleLaunchFilesError(
            f"file '{file_name}' was found more than once in the share directory of package "
            f"'{package_name}': [{', '.join(repr(m) for m in sorted(matches))}]")
    return matches[0]


def parse_launch_arguments(arguments: list[str]) -> list[tuple[str, str]]:
    """`name:=value` words as (name, value); for duplicates the last one wins."""
    parsed: dict[str, str] = {}
    for argument in arguments:
        count = argument.count(':=')
        if count == 0 or argument.startswith(':=') or (count == 1 and argument.endswith(':=')):
            raise ValueError(f"malformed launch argument '{argument}', expected format "
                             "'<name>:=<value>'")
        name, value = argument.split(':=', 1)
        parsed[name] = value
    return list(parsed.items())


def print_a_launch_file(*, launch_file_path: str) -> None:
    description = get_launch_description_from_any_launch_file(launch_file_path)
    print(launch.LaunchIntrospector().format_launch_description(description))


def print_arguments_of_launch_file(*, launch_file_path: str) -> None:
    print_arguments_of_launch_description(
        launch_description=get_launch_description_from_any_launch_file(launch_file_path))


def print_arguments_of_launch_description(*, launch_description: launch.LaunchDescription
                                          ) -> None:
    """The declared arguments, those of included launch files too (`--show-args`)."""
    description = launch_description
    print("Arguments (pass arguments as '<name>:=<value>'):")
    arguments = description.get_launch_arguments()
    any_conditional = False
    for argument in arguments:
        text = f"\n    '{argument.name}':"
        if argument._conditionally_included:
            any_conditional = True
            text += '*'
        text += f'\n        {argument.description}'
        if argument.default_value is not None:
            default = ' + '.join(sub.describe() for sub in argument.default_value)
            text += f'\n        (default: {default})'
        print(text)
    if not arguments:
        print('\n  No arguments.')
    elif any_conditional:
        print('\n* argument(s) which are only used if specific conditions occur')


def launch_a_launch_file(*, launch_file_path: str, launch_file_arguments: list[str],
                         noninteractive: bool = False, debug: bool = False) -> int:
    arguments = parse_launch_arguments(launch_file_arguments)
    service = launch.LaunchService(argv=launch_file_arguments, noninteractive=noninteractive,
                                   debug=debug)
    service.include_launch_description(launch.LaunchDescription([
        IncludeLaunchDescription(AnyLaunchDescriptionSource(launch_file_path),
                                 launch_arguments=arguments),
    ]))
    return service.run()
