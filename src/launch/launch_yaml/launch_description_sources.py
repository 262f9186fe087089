"""launch_yaml.launch_description_sources: where upstream launch files import it from."""

from launch.launch_description_sources import YAMLLaunchDescriptionSource

__all__ = ['YAMLLaunchDescriptionSource']
