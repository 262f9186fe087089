"""SetUseSimTime: the launch's own ROS node (ROSTimer's clock) follows /clock."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.frontend import expose_action
from launch.utilities.type_utils import perform_typed_substitution
from rclpy.parameter import Parameter

from launch_ros.ros_adapters import get_ros_node

if TYPE_CHECKING:
    from launch.frontend import Entity, Parser
    from launch.launch_context import LaunchContext


@expose_action('set_use_sim_time')
class SetUseSimTime(Action):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs['value'] = parser.parse_substitution(entity.get_attr('value'))
        return cls, kwargs

    def __init__(self, value: bool, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__value = value

    @property
    def value(self) -> Any:
        return self.__value

    def execute(self, context: LaunchContext) -> None:
        value = self.__value if isinstance(self.__value, bool) else \
            perform_typed_substitution(context, self.__value, bool)
        node = get_ros_node(context)
        node.set_parameters([Parameter('use_sim_time', Parameter.Type.BOOL, value)])
        if node.get_parameter('use_sim_time').value != value:
            raise RuntimeError('Failed to set use_sim_time parameter')
