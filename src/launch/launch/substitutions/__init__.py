"""launch.substitutions: values worked out when the launch runs."""

import os

from launch._missing import module_getattr
from launch.substitution import TextSubstitution
from launch.substitutions.basic import (
                                        AnonName,
                                        Command,
                                        EnvironmentVariable,
                                        FindExecutable,
                                        LaunchConfiguration,
                                        LocalSubstitution,
                                        PathJoinSubstitution,
                                        PythonExpression,
                                        ThisLaunchFile,
                                        ThisLaunchFileDir,
)
from launch.substitutions.substitution_failure import SubstitutionFailure

__all__ = [
    'AnonName', 'Command', 'EnvironmentVariable', 'FindExecutable', 'LaunchConfiguration',
    'LocalSubstitution', 'PathJoinSubstitution', 'PythonExpression', 'SubstitutionFailure',
    'TextSubstitution', 'ThisLaunchFile', 'ThisLaunchFileDir',
]

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
