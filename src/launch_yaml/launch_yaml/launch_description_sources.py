"""launch_yaml.launch_description_sources: YAML launch files, whatever their names end with."""

from __future__ import annotations

from typing import Any

from launch.launch_description_sources import FrontendLaunchDescriptionSource

from launch_yaml.parser import Parser


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(launch_file_path, method='interpreted YAML launch file', parser=Parser)


__all__ = ['YAMLLaunchDescriptionSource']
