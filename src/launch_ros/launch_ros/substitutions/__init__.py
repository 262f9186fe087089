"""launch_ros.substitutions: package paths, executables and parameters set in the launch."""

import os

from launch._missing import module_getattr

from launch_ros.substitutions.executable_in_package import ExecutableInPackage
from launch_ros.substitutions.find_package import FindPackagePrefix, FindPackageShare
from launch_ros.substitutions.parameter import Parameter

__all__ = ['ExecutableInPackage', 'FindPackagePrefix', 'FindPackageShare', 'Parameter']

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
