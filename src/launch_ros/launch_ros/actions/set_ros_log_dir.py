"""SetROSLogDir: where the nodes started after it write their logs (ROS_LOG_DIR); a relative
directory is taken inside the current one."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.frontend import expose_action
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from launch.frontend import Entity, Parser
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType


def _current_log_dir() -> str:
    """ROS_LOG_DIR, else rcl's default (ROS_HOME/log, ~/.ros/log)."""
    if os.environ.get('ROS_LOG_DIR'):
        return os.environ['ROS_LOG_DIR']
    ros_home = os.environ.get('ROS_HOME') or os.path.join(os.path.expanduser('~'), '.ros')
    return os.path.join(ros_home, 'log')


@expose_action('set_ros_log_dir')
class SetROSLogDir(Action):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs['new_log_dir'] = parser.parse_substitution(entity.get_attr('new_log_dir'))
        return cls, kwargs

    def __init__(self, new_log_dir: SomeSubstitutionsType, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__log_dir = normalize_to_list_of_substitutions(new_log_dir)

    @property
    def log_dir(self) -> list[Any]:
        return self.__log_dir

    def execute(self, context: LaunchContext) -> None:
        log_dir = os.path.join(_current_log_dir(), perform_substitutions(context, self.log_dir))
        # Upstream sets the launch process's own environment, which PushEnvironment saves.
        os.environ['ROS_LOG_DIR'] = log_dir
        context.environment['ROS_LOG_DIR'] = log_dir
