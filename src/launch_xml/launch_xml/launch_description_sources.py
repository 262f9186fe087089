"""launch_xml.launch_description_sources: XML launch files, whatever their names end with."""

from __future__ import annotations

from typing import Any

from launch.launch_description_sources import FrontendLaunchDescriptionSource

from launch_xml.parser import Parser


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(launch_file_path, method='interpreted XML launch file', parser=Parser)


__all__ = ['XMLLaunchDescriptionSource']
