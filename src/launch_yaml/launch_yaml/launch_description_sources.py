"""launch_yaml.launch_description_sources: YAML launch files, whatever their names end with."""

from __future__ import annotations

from launch.launch_description_sources import FrontendLaunchDescriptionSource
from launch.substitution import SomeSubstitutionsType


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    file_format = 'yaml'

    def __init__(self, launch_file_path: SomeSubstitutionsType) -> None:
        super().__init__(launch_file_path, method='interpreted YAML launch file')


__all__ = ['YAMLLaunchDescriptionSource']
