"""Keep rclpy's parameter services alive under any request.

rclpy 7.1.6 builds each requested value with `Parameter.from_parameter_msg`, which raises
ValueError for a type byte that names no parameter type (e.g. 165, found by fuzzing). The
exception escapes the service callback, ends the executor's spin and so stops every callback
of the node. Here such a request is refused like any other bad value: one result per
parameter with `successful: false` and a reason naming the parameter and what is allowed.
"""

from __future__ import annotations

from rcl_interfaces.msg import Parameter as ParameterMsg
from rcl_interfaces.msg import ParameterType, SetParametersResult
from rcl_interfaces.srv import SetParameters, SetParametersAtomically
from rclpy.node import Node

_TYPES = {value for name, value in vars(ParameterType).items()
          if name.startswith('PARAMETER_') and isinstance(value, int)}
ALLOWED_TYPES = f'{min(_TYPES)}..{max(_TYPES)} (rcl_interfaces/msg/ParameterType)'


def request_problem(node: Node, parameter: ParameterMsg) -> str | None:
    """Why rclpy cannot take this parameter, or None. Undeclared names are refused here too:
    rclpy's own reason ('Invalid access to undeclared parameter(s): []') names no parameter,
    and it takes an undeclared '' as a success."""
    if parameter.value.type not in _TYPES:
        return (f'parameter {parameter.name!r} has type {parameter.value.type}, which is no '
                f'parameter type (allowed: {ALLOWED_TYPES})')
    if not node.has_parameter(parameter.name):
        declared = ', '.join(sorted(node._parameters))
        return f'parameter {parameter.name!r} is not declared (declared: {declared})'
    return None


def guard_parameter_services(node: Node) -> None:
    """Wrap the node's set_parameters and set_parameters_atomically callbacks."""
    for service in node.services:
        if service.srv_type is SetParameters:
            service.callback = _guarded_set(node, service.callback)
        elif service.srv_type is SetParametersAtomically:
            service.callback = _guarded_atomically(node, service.callback)


def _refused(node: Node, reason: str) -> SetParametersResult:
    node.get_logger().error(f'Refusing to set {reason}')
    return SetParametersResult(successful=False, reason=reason)


def _guarded_set(node: Node, callback):
    def set_parameters(request: SetParameters.Request,
                       response: SetParameters.Response) -> SetParameters.Response:
        for parameter in request.parameters:
            problem = request_problem(node, parameter)
            if problem:
                response.results.append(_refused(node, problem))
            else:
                single = SetParameters.Request(parameters=[parameter])
                for result in callback(single, SetParameters.Response()).results:
                    response.results.append(_naming(parameter.name, result))
        return response
    return set_parameters


def _guarded_atomically(node: Node, callback):
    def set_parameters_atomically(
            request: SetParametersAtomically.Request,
            response: SetParametersAtomically.Response) -> SetParametersAtomically.Response:
        for parameter in request.parameters:
            problem = request_problem(node, parameter)
            if problem:
                response.result = _refused(node, problem)
                return response
        response = callback(request, response)
        if request.parameters:
            response.result = _naming(', '.join(p.name for p in request.parameters),
                                      response.result)
        return response
    return set_parameters_atomically


def _naming(name: str, result: SetParametersResult) -> SetParametersResult:
    """rclpy's own refusals ('Static parameter cannot be undeclared', 'Wrong parameter type,
    expected ...') do not say which parameter: prefix its name."""
    if not result.successful and name not in result.reason:
        result.reason = f'parameter {name}: {result.reason}'
    return result
