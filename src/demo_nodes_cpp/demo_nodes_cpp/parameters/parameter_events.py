"""`ros2 run demo_nodes_cpp parameter_events` (and `..._async`): logs the /parameter_events of
its own parameter changes (two rounds of sets) until it has seen ten events."""
import sys
import time

from node_runtime.spinning import SIGNAL_CHECK_PERIOD, ros_session
from rcl_interfaces.msg import ParameterEvent
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import qos_profile_parameter_events

from demo_nodes_cpp.parameters.self_client import answer, self_client

EVENTS = 10
MAXIMUM_WAIT = 30.0  # seconds for the ten events


def describe(event: ParameterEvent) -> str | None:
    """rclcpp's text of an event; None for one with only the qos_overrides declarations."""
    new = [parameter.name for parameter in event.new_parameters
           if not parameter.name.startswith('qos_overrides.')]
    changed = [parameter.name for parameter in event.changed_parameters]
    deleted = [parameter.name for parameter in event.deleted_parameters]
    if not (new or changed or deleted):
        return None
    lines = ['', 'Parameter event:', ' new parameters:', *(f'  {name}' for name in new),
             ' changed parameters:', *(f'  {name}' for name in changed),
             ' deleted parameters:', *(f'  {name}' for name in deleted), '']
    return '\n'.join(lines)


def main(name: str = 'parameter_events') -> int:
    with ros_session() as stop:
        node = Node(name)
        client = self_client(node, stop)
        if client is None:
            return 0
        seen = []

        def on_event(event: ParameterEvent) -> None:
            text = describe(event)
            if text is not None:
                seen.append(event)
                node.get_logger().info(text)

        subscription = node.create_subscription(ParameterEvent, '/parameter_events', on_event,
                                                qos_profile_parameter_events)
        deadline = time.monotonic() + 2.0  # matched with the node's own publisher first
        while subscription.get_publisher_count() == 0 and time.monotonic() < deadline:
            time.sleep(0.01)
        for parameter, value in (('foo', 0), ('bar', ''), ('baz', 0.0), ('foobar', False)):
            node.declare_parameter(parameter, value)
        for values in ((('foo', 2), ('bar', 'hello'), ('baz', 1.45), ('foobar', True)),
                       (('foo', 3), ('bar', 'world'))):
            results = answer(node, client.set_parameters(
                [Parameter(parameter, value=value) for parameter, value in values]), stop)
            for result in results.results if results else []:
                if not result.successful:
                    node.get_logger().error(f'Failed to set parameter: {result.reason}')
        executor = SingleThreadedExecutor()
        executor.add_node(node)
        deadline = time.monotonic() + MAXIMUM_WAIT
        while len(seen) < EVENTS and not stop.is_set() and time.monotonic() < deadline:
            executor.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
        executor.shutdown(timeout_sec=1.0)
        node.destroy_node()
    return 0


def main_async() -> int:
    return main('parameter_events')


if __name__ == '__main__':
    sys.exit(main())
