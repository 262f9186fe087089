"""LoadComposableNodes, and the LoadNode request a component container would be sent.

Loading needs a running component container (rclcpp_components), which this workspace does
not have: the action fails with one line saying so. The request itself is built as upstream
builds it (namespace, SetRemap / SetParameter / SetParametersFromFile, the node's own
parameters), so launch files describing composable nodes can be checked.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.utilities import perform_substitutions

from launch_ros.descriptions import ComposableNode, ParameterFile
from launch_ros.utilities import (
    evaluate_parameters,
    make_namespace_absolute,
    normalize_parameter_dict,
    prefix_namespace,
    to_parameters_list,
)

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType

    from launch_ros.actions.composable_node_container import ComposableNodeContainer

NO_CONTAINERS = ('{what}: composable nodes need a component container (rclcpp_components), '
                 'which this workspace does not have; start the nodes with '
                 'launch_ros.actions.Node instead (see docs/launch.md)')


class LoadComposableNodes(Action):
    def __init__(self, *, composable_node_descriptions: list[ComposableNode],
                 target_container: SomeSubstitutionsType | ComposableNodeContainer,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.__descriptions = list(composable_node_descriptions)
        self.__target_container = target_container

    def execute(self, context: LaunchContext) -> None:
        raise RuntimeError(NO_CONTAINERS.format(what='LoadComposableNodes'))


def get_composable_node_load_request(description: ComposableNode, context: Any) -> Any:
    """The composition_interfaces LoadNode request for a composable node, or None when its
    condition is false."""
    import composition_interfaces.srv
    condition = description.condition()
    if condition is not None and not condition.evaluate(context):
        return None
    request = composition_interfaces.srv.LoadNode.Request()
    request.package_name = perform_substitutions(context, description.package)
    request.plugin_name = perform_substitutions(context, description.node_plugin)
    if description.node_name is not None:
        request.node_name = perform_substitutions(context, description.node_name)
    namespace = None if description.node_namespace is None else perform_substitutions(
        context, description.node_namespace)
    namespace = make_namespace_absolute(prefix_namespace(
        context.launch_configurations.get('ros_namespace'), namespace))
    if namespace is not None:
        request.node_namespace = namespace
    rules = [f'{src}:={dst}' for src, dst in context.launch_configurations.get('ros_remaps')
             or ()]
    rules += [f'{perform_substitutions(context, list(src))}:='
              f'{perform_substitutions(context, list(dst))}'
              for src, dst in description.remappings or ()]
    if rules:
        request.remap_rules = rules
    parameters: list[Any] = []
    for item in context.launch_configurations.get('global_params') or ():
        if isinstance(item, tuple):  # SetParameter's (name, value)
            parameters.append(normalize_parameter_dict({item[0]: item[1]}))
        else:  # SetParametersFromFile's path
            parameters.append(ParameterFile(Path(item).resolve()))
    parameters += list(description.parameters or ())

    def messages(items: Any) -> list[Any]:
        return [p.to_parameter_msg() for p in to_parameters_list(
            context, request.node_name, namespace or '', evaluate_parameters(context, items))]

    if parameters:
        request.parameters = messages(parameters)
    if description.extra_arguments is not None:
        request.extra_arguments = messages(description.extra_arguments)
    return request
