"""ThisLaunchFileDir: `$(dirname)`, the directory of the launch file being read."""

from launch.frontend.expose import expose_substitution
from launch.substitutions.this_launch_file import ThisLaunchFile


@expose_substitution('dirname')
class ThisLaunchFileDir(ThisLaunchFile):
    _local = 'current_launch_file_directory'
    _tag = 'dirname'
