"""Loading an XML or YAML launch file through the installed front ends."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.frontend.parser import InvalidFrontendLaunchFileError, Parser

if TYPE_CHECKING:
    from launch.launch_description import LaunchDescription

__all__ = ['InvalidFrontendLaunchFileError', 'get_launch_description_from_frontend_launch_file']


def get_launch_description_from_frontend_launch_file(
        frontend_launch_file_path: str, *, parser: type[Parser] = Parser) -> LaunchDescription:
    root, parser_instance = parser.load(frontend_launch_file_path)
    return parser_instance.parse_description(root)
