"""Loading a launch file of any format: the loader its name suggests first, then the others."""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import TYPE_CHECKING

from launch.frontend.parser import Parser
from launch.invalid_launch_file_error import InvalidLaunchFileError
from launch.launch_description_sources.frontend_launch_file_utilities import (
    get_launch_description_from_frontend_launch_file,
)
from launch.launch_description_sources.python_launch_file_utilities import (
    get_launch_description_from_python_launch_file,
)

if TYPE_CHECKING:
    from launch.launch_description import LaunchDescription


def get_launch_description_from_any_launch_file(launch_file_path: str, *,
                                                parser: type[Parser] = Parser
                                                ) -> LaunchDescription:
    loaders: list[Callable[[str], LaunchDescription]] = [
        get_launch_description_from_frontend_launch_file]
    name = os.path.basename(launch_file_path)
    extension = os.path.splitext(name)[1][1:]
    if extension == 'py':
        loaders.insert(0, get_launch_description_from_python_launch_file)
    else:
        loaders.append(get_launch_description_from_python_launch_file)
        if not Parser.is_filename_valid(name):
            extension = ''
    errors: list[Exception] = []
    for loader in loaders:
        try:
            return loader(launch_file_path)
        except Exception as error:
            errors.append(error)
    if extension:
        # The loader the file's name asks for tells what is wrong; the others' failures
        # ("not XML", "not Python") would only hide it.
        errors = errors[:1]
    raise InvalidLaunchFileError(extension, likely_errors=errors)
