"""launch_xml.launch_description_sources: where upstream launch files import it from."""

from launch.launch_description_sources import XMLLaunchDescriptionSource

__all__ = ['XMLLaunchDescriptionSource']
