"""launch_xml.launch_description_sources: XML launch files, whatever their names end with."""

from __future__ import annotations

from launch.launch_description_sources import FrontendLaunchDescriptionSource
from launch.substitution import SomeSubstitutionsType


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    file_format = 'xml'

    def __init__(self, launch_file_path: SomeSubstitutionsType) -> None:
        super().__init__(launch_file_path, method='interpreted XML launch file')


__all__ = ['XMLLaunchDescriptionSource']
