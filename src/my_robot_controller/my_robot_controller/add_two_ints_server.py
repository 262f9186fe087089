"""Serve /add_two_ints: answer each request with the sum of its two integers."""

from example_interfaces.srv import AddTwoInts
from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import SetParametersResult
from rclpy.exceptions import InvalidParameterTypeException, InvalidParameterValueException
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import qos_profile_system_default
from rclpy.service_introspection import ServiceIntrospectionState

from my_robot_controller.int64 import INT64_RANGE, fits_int64

# As ros2/demos' introspection_service, when started with `--ros-args -p
# service_configure_introspection:=disabled` (or any of the states): `ros2 param set
# /add_two_ints_server service_configure_introspection contents` then lets `ros2 service echo
# /add_two_ints` see calls. Without that override the node has demo_nodes_py's parameters.
INTROSPECTION_PARAMETER = 'service_configure_introspection'
INTROSPECTION_STATES = {'disabled': ServiceIntrospectionState.OFF,
                        'metadata': ServiceIntrospectionState.METADATA,
                        'contents': ServiceIntrospectionState.CONTENTS}


class AddTwoIntsServer(Node):
    def __init__(self) -> None:
        super().__init__('add_two_ints_server')
        self.service = self.create_service(AddTwoInts, 'add_two_ints', self.on_add_two_ints)
        self.add_on_set_parameters_callback(self.on_set_parameters)
        self.add_post_set_parameters_callback(self.on_parameters_set)
        # rclpy keeps the start-up overrides (-p, params files) in this attribute only.
        if INTROSPECTION_PARAMETER in self._parameter_overrides:
            try:
                self.declare_parameter(INTROSPECTION_PARAMETER, 'disabled')
            except (InvalidParameterValueException, InvalidParameterTypeException) as error:
                self.get_logger().error(f'Ignoring the command-line value: {error}')
                self.declare_parameter(INTROSPECTION_PARAMETER, 'disabled', ignore_override=True)
        self.get_logger().info('Ready to add two ints on /add_two_ints')

    def on_set_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            if parameter.name == INTROSPECTION_PARAMETER and (
                    parameter.type_ != Parameter.Type.STRING
                    or parameter.value not in INTROSPECTION_STATES):
                return SetParametersResult(
                    successful=False, reason=f'{INTROSPECTION_PARAMETER} must be one of '
                    f"{', '.join(INTROSPECTION_STATES)}, got {parameter.value!r}")
        return SetParametersResult(successful=True)

    def on_parameters_set(self, parameters: list[Parameter]) -> None:
        for parameter in parameters:
            if parameter.name == INTROSPECTION_PARAMETER:
                self.service.configure_introspection(
                    self.get_clock(), qos_profile_system_default,
                    INTROSPECTION_STATES[parameter.value])

    def on_add_two_ints(self, request: AddTwoInts.Request,
                        response: AddTwoInts.Response) -> AddTwoInts.Response:
        total = request.a + request.b
        self.get_logger().info(f'Incoming request: a={request.a} b={request.b}')
        if not fits_int64(total):
            # The interface has no error field: answer 0 and say why, never crash.
            self.get_logger().error(
                f'sum {request.a} + {request.b} = {total} does not fit in int64 '
                f'{INT64_RANGE}; answering sum=0')
            response.sum = 0
            return response
        response.sum = total
        self.get_logger().info(f'Sending back sum={total}')
        return response


def main(args: list[str] | None = None) -> None:
    with ros_session(args) as stop:
        spin_until_stopped(AddTwoIntsServer(), stop)


if __name__ == '__main__':
    main()
