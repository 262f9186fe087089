"""launch.frontend: XML and YAML launch files, parsed into the actions a Python file builds.

As upstream: each action and substitution registers its own tag with `expose_action` /
`expose_substitution` (launch's here, launch_ros's in launch_ros), and the front ends that
read a file format into `Entity` trees live in their own packages, launch_xml and
launch_yaml, found through the `launch.frontend.parser` entry point group.
"""

from launch.frontend import type_utils
from launch.frontend.entity import Entity, FrontendError
from launch.frontend.expose import expose_action, expose_substitution
from launch.frontend.parse_substitution import parse_substitution
from launch.frontend.parser import Parser

__all__ = ['Entity', 'FrontendError', 'Parser', 'expose_action', 'expose_substitution',
           'parse_substitution', 'type_utils']
