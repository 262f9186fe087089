"""ComposableNodeContainer: a component container with composable nodes loaded into it.

The container executables (rclcpp_components' component_container) do not exist in this
workspace; launching one fails with one line saying so (see load_composable_nodes).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch_ros.actions.load_composable_nodes import NO_CONTAINERS
from launch_ros.actions.node import Node

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType

    from launch_ros.descriptions import ComposableNode


class ComposableNodeContainer(Node):
    def __init__(self, *, name: SomeSubstitutionsType, namespace: SomeSubstitutionsType,
                 composable_node_descriptions: list[ComposableNode] | None = None,
                 **kwargs: Any) -> None:
        super().__init__(name=name, namespace=namespace, **kwargs)
        self.__descriptions = list(composable_node_descriptions or [])

    def execute(self, context: LaunchContext) -> Any:
        raise RuntimeError(NO_CONTAINERS.format(what='ComposableNodeContainer'))
