"""`ros2 run demo_nodes_py async_param_client`: sets, lists, gets, loads (params.yaml) and
deletes parameters of a running parameter_blackboard through AsyncParameterClient."""
from __future__ import annotations

import os
import sys
import threading

import rclpy
from ament_index_python import get_package_share_directory
from node_runtime.spinning import ros_session
from rclpy.node import Node
from rclpy.parameter import Parameter, parameter_dict_from_yaml_file, parameter_value_to_python
from rclpy.parameter_client import AsyncParameterClient
from rclpy.task import Future

from demo_nodes_py.services.client_wait import spin_until_done

PARAMS = ['int_parameter', 'bool_parameter', 'string_parameter']
TO_DELETE = ['other_int_parameter', 'other_string_parameter', 'string_parameter']


def answer(node: Node, future: Future, stop: threading.Event, what: str):
    """The response, or None after logging why there is none."""
    if spin_until_done(node, future, stop) and future.result() is not None:
        return future.result()
    node.get_logger().error(f'Error {what}: {future.exception()}')
    return None


def run(node: Node, client: AsyncParameterClient, stop: threading.Event) -> None:
    log = node.get_logger()
    log.info('Setting parameters:')
    result = answer(node, client.set_parameters([
        Parameter('int_parameter', Parameter.Type.INTEGER, 10),
        Parameter('bool_parameter', Parameter.Type.BOOL, False),
        Parameter('string_parameter', Parameter.Type.STRING, 'Fee Fi Fo Fum')]),
        stop, 'setting parameters')
    for name, each in zip(PARAMS, result.results if result else [], strict=False):
        log.info(f'    {name}:')
        log.info(f'        successful: {each.successful}')

    log.info('Listing Parameters:')
    result = answer(node, client.list_parameters(PARAMS, 10), stop, 'listing parameters')
    for name in result.result.names if result else []:
        log.info(f'    - {name}')

    log.info('Getting parameters:')
    result = answer(node, client.get_parameters(PARAMS), stop, 'getting parameters')
    for name, value in zip(PARAMS, result.values if result else [], strict=False):
        log.info(f'    - {name}: {parameter_value_to_python(value)}')

    log.info('Loading parameters: ')
    path = os.path.join(get_package_share_directory('demo_nodes_py'), 'params.yaml')
    result = answer(node, client.load_parameter_file(path), stop, 'loading parameters')
    if result:
        from_file = parameter_dict_from_yaml_file(path)
        for (name, parameter), each in zip(from_file.items(), result.results, strict=False):
            log.info(f'    {name}:')
            log.info(f'        successful: {each.successful}')
            log.info(f'        value: {parameter_value_to_python(parameter.value)}')

    log.info('Deleting parameters: ')
    result = answer(node, client.delete_parameters(TO_DELETE), stop, 'deleting parameters')
    for name, each in zip(TO_DELETE, result.results if result else [], strict=False):
        log.info(f'    {name}:')
        log.info(f'        successful: {each.successful}')
        log.info(f'        reason: {each.reason}')


def main() -> int:
    with ros_session() as stop:
        node = rclpy.create_node('async_param_client')
        client = AsyncParameterClient(node, 'parameter_blackboard')
        if not client.wait_for_services(3.0):
            node.get_logger().error(
                'parameter_blackboard is not available, start parameter blackboard with '
                '`ros2 run demo_nodes_cpp parameter_blackboard` before running this demo')
            return 1
        run(node, client, stop)
        node.destroy_node()
    return 0


if __name__ == '__main__':
    sys.exit(main())
