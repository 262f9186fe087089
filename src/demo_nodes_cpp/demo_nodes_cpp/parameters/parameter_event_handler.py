"""`ros2 run demo_nodes_cpp parameter_event_handler`: a ParameterEventHandler of node
`this_node` calls back on changes of its own `an_int_param` (cb1), of `a_string_param` of
/a_namespace/a_remote_node (cb2, a node of the same process), and on every parameter event of
those two nodes (cb3)."""
import re
import sys

from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import Parameter as ParameterMsg
from rcl_interfaces.msg import ParameterEvent
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_event_handler import ParameterEventHandler

from demo_nodes_cpp.rclcpp_node import type_name, value_to_string

NODE_NAME, PARAM_NAME = 'this_node', 'an_int_param'
REMOTE_NAME, REMOTE_NAMESPACE, REMOTE_PARAM = 'a_remote_node', '/a_namespace', 'a_string_param'
REMOTE_FQN = f'{REMOTE_NAMESPACE}/{REMOTE_NAME}'
WATCHED = re.compile(r'(/a_namespace/.*)|(/this_node)')
INSTRUCTIONS = f'''This demo is monitoring for the following parameter changes:

\tnode: "{NODE_NAME}"
\tparameter: "{PARAM_NAME}"

\tnode: "{REMOTE_FQN}"
\tparameter: "{REMOTE_PARAM}"

To activate the callbacks, from a separate shell/console window, execute either of the \
following example commands:

\t$ ros2 param set {NODE_NAME} {PARAM_NAME} 21
\t$ ros2 param set {REMOTE_FQN} {REMOTE_PARAM} "string value to set"
'''


def main() -> int:
    with ros_session() as stop:
        node = Node(NODE_NAME)
        node.declare_parameter(PARAM_NAME, 0)
        remote = Node(REMOTE_NAME, namespace=REMOTE_NAMESPACE)
        remote.declare_parameter(REMOTE_PARAM, 'default_string_value')
        log = node.get_logger()

        # rclpy's handler passes rcl_interfaces/msg/Parameter messages; rclcpp passes Parameters.
        def cb1(message: ParameterMsg) -> None:
            parameter = Parameter.from_parameter_msg(message)
            log.info(f'cb1: Received an update to parameter "{parameter.name}" of type '
                     f'{type_name(parameter)}: "{parameter.value}"')

        def cb2(message: ParameterMsg) -> None:
            parameter = Parameter.from_parameter_msg(message)
            log.info(f'cb2: Received an update to parameter "{parameter.name}" of type: '
                     f'{type_name(parameter)}: "{parameter.value}"')

        def cb3(event: ParameterEvent) -> None:
            if not WATCHED.fullmatch(event.node):
                return
            changed = ParameterEventHandler.get_parameter_from_event(
                event, parameter_name=REMOTE_PARAM, node_name=REMOTE_FQN)
            shown = ([changed] if changed is not None else []) + list(
                ParameterEventHandler.get_parameters_from_event(event))
            for parameter in map(Parameter.from_parameter_msg, shown):
                log.info(f'cb3: Received an update to parameter "{parameter.name}" of type: '
                         f'{type_name(parameter)}: "{value_to_string(parameter)}"')

        handler = ParameterEventHandler(node)
        handles = (handler.add_parameter_callback(PARAM_NAME, NODE_NAME, cb1),
                   handler.add_parameter_callback(REMOTE_PARAM, REMOTE_FQN, cb2),
                   handler.add_parameter_event_callback(cb3))
        print(INSTRUCTIONS, flush=True)
        executor = SingleThreadedExecutor()
        executor.add_node(remote)
        spin_until_stopped(node, stop, executor)
        del handles
    return 0


if __name__ == '__main__':
    sys.exit(main())
