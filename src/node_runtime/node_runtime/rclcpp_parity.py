"""What C++ (rclcpp) nodes show the graph because rclcpp made them, added to rclpy stand-ins.

Every rclcpp node declares read-only `qos_overrides./parameter_events.publisher.*` parameters
(the QoS of its /parameter_events publisher) and subscribes to /parameter_events; rclpy
nodes do neither. The tutorials' `ros2 param list`, `param dump`, `param load` and `ros2 node
info` listings show them, so the stand-ins for rclcpp nodes (turtlesim, teleop, mimic,
draw_square, demo_nodes_cpp's parameter_blackboard) declare them too, with rclcpp's values and
rclcpp's refusal text for a read-only parameter.

A managed (lifecycle) node asked for a transition its state does not offer: rclpy raises out
of the change_state service, which ends the node; rclcpp logs one line, answers
success=False and stays where it was. `RclcppLifecycleTransitions` gives rclpy's
lifecycle nodes rclcpp's behaviour.
"""

from __future__ import annotations

from rcl_interfaces.msg import ParameterDescriptor, ParameterEvent, SetParametersResult
from rclpy.exceptions import InvalidParameterTypeException, InvalidParameterValueException
from rclpy.lifecycle import TransitionCallbackReturn
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import qos_profile_parameter_events

PREFIX = 'qos_overrides./parameter_events.publisher.'
# rclpy's /parameter_events publisher uses exactly this profile, as rclcpp's does.
PARAMETER_EVENT_QOS_VALUES = (
    ('depth', qos_profile_parameter_events.depth),
    ('durability', 'volatile'),
    ('history', 'keep_last'),
    ('reliability', 'reliable'),
)


class RclcppParameters:
    """Mixin for a Node: a refused read-only parameter or wrong type reads as rclcpp words it."""

    def _apply_descriptors(self, parameter_list, descriptors, check_read_only=True):
        if check_read_only:
            for parameter in parameter_list:
                descriptor = descriptors.get(parameter.name)
                if descriptor is not None and descriptor.read_only:
                    return SetParametersResult(
                        successful=False, reason=f"parameter '{parameter.name}' cannot be set "
                        'because it is read-only')
        return super()._apply_descriptors(parameter_list, descriptors, check_read_only)

    def _apply_descriptor(self, parameter, descriptor=None, check_read_only=True):
        result = super()._apply_descriptor(parameter, descriptor, check_read_only)
        if not result.successful and result.reason.startswith('Wrong parameter type, expected'):
            # rclcpp's words (the "Using the ros2 param command-line tool" page's `off`).
            declared = Parameter.Type((descriptor or self.describe_parameter(parameter.name)).type)
            result.reason = (
                f'Wrong parameter type, parameter {{{parameter.name}}} is of type '
                f'{{{_rclcpp_type_name(declared)}}}, setting it to '
                f'{{{_rclcpp_type_name(parameter.type_)}}} is not allowed.')
        return result


class RclcppLifecycleTransitions:
    """Mixin for an rclpy.lifecycle.Node: a transition the current state does not offer is
    refused with rclcpp's error line, and the node keeps running."""

    def _LifecycleNodeMixin__change_state(self, transition_id: int) -> TransitionCallbackReturn:
        # overrides rclpy's private (name-mangled) __change_state, which raises for it
        label = self._state_machine.current_state[1]
        if transition_id not in {t[0] for t in self._state_machine.available_transitions}:
            self.get_logger().error(f'Unable to start transition {transition_id} from current '
                                    f'state {label}: Transition is not registered.')
            return TransitionCallbackReturn.FAILURE
        return super()._LifecycleNodeMixin__change_state(transition_id)


def _rclcpp_type_name(kind: Parameter.Type) -> str:
    """rclcpp::to_string(ParameterType): 'bool', 'integer_array', 'not set'."""
    return kind.name.lower().replace('not_set', 'not set')


def declare_rclcpp_parameters(node: Node, subscribe_parameter_events: bool = True) -> None:
    """Declare the qos_overrides parameters (a params file may set them at start-up, as in
    rclcpp) and, unless the node has its own, a /parameter_events subscription."""
    for name, default in PARAMETER_EVENT_QOS_VALUES:
        if node.has_parameter(PREFIX + name):
            continue  # declared from an override (automatically_declare_parameters_from_overrides)
        descriptor = ParameterDescriptor(read_only=True)
        try:
            node.declare_parameter(PREFIX + name, default, descriptor)
        except (InvalidParameterValueException, InvalidParameterTypeException):
            node.get_logger().error(f'Ignoring the command-line value of {PREFIX}{name}; '
                                    f'using the default {default!r}')
            node.declare_parameter(PREFIX + name, default, descriptor, ignore_override=True)
    if subscribe_parameter_events:
        node.create_subscription(ParameterEvent, '/parameter_events', lambda _event: None,
                                 qos_profile_parameter_events)
