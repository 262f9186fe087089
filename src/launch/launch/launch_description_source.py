"""LaunchDescriptionSource: where a launch description comes from (given, or a file)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from launch.launch_context import LaunchContext
from launch.logging import get_logger
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.launch_description import LaunchDescription
    from launch.some_substitutions_type import SomeSubstitutionsType


class LaunchDescriptionSource:
    def __init__(self, launch_description: LaunchDescription | None = None,
                 location: SomeSubstitutionsType = '<string>',
                 method: str = 'unspecified mechanism from a script') -> None:
        self.__launch_description = launch_description
        self.__location = normalize_to_list_of_substitutions(location)
        self.__expanded_location: str | None = None
        self.__method = method

    def try_get_launch_description_without_context(self) -> LaunchDescription | None:
        """The description, loaded with an empty context if need be (for --show-args and
        introspection); None when that cannot be done (e.g. the path needs an argument)."""
        if self.__launch_description is not None:
            return self.__launch_description
        try:
            return self._get_launch_description(
                perform_substitutions(LaunchContext(), self.__location))
        except Exception as error:
            get_logger('launch').debug(f'Failed to load the launch file without a context: '
                                       f'{error}')
            return None

    def get_launch_description(self, context: LaunchContext) -> LaunchDescription:
        if self.__expanded_location is None:
            self.__expanded_location = perform_substitutions(context, self.__location)
        if self.__launch_description is None:
            self.__launch_description = self._get_launch_description(
                self.__expanded_location)
        return self.__launch_description

    def _get_launch_description(self, location: str) -> LaunchDescription:
        """A subclass loads the file at `location`; the base class has nothing to load."""
        if self.__launch_description is None:
            raise RuntimeError('LaunchDescriptionSource.get_launch_description(): called '
                               'without launch description being set')
        return self.__launch_description

    @property
    def location(self) -> str:
        if self.__expanded_location is None:
            return ' + '.join(str(sub) for sub in self.__location)
        return self.__expanded_location

    @property
    def method(self) -> str:
        return self.__method
