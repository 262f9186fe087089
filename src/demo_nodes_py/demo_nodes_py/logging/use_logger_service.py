"""`ros2 run demo_nodes_py use_logger_service`: a node with the logger services
(`enable_logger_service=True`) logs each message it hears at four severities; a second node
sets that node's logger level through `set_logger_levels` (debug, warn, error), reads it back
through `get_logger_levels`, and sends a message at each level."""
from __future__ import annotations

import sys
import threading
import time

from node_runtime.spinning import ros_session
from rcl_interfaces.msg import LoggerLevel
from rcl_interfaces.srv import GetLoggerLevels, SetLoggerLevels
from rclpy.executors import SingleThreadedExecutor
from rclpy.impl.logging_severity import LoggingSeverity
from rclpy.node import Node
from std_msgs.msg import String

from demo_nodes_py.services.client_wait import spin_until_done

SERVICE_WAIT = 5.0  # seconds for the logger services to be discovered


class LoggerServiceNode(Node):
    def __init__(self, name: str = 'LoggerServiceNode') -> None:
        super().__init__(name, enable_logger_service=True)
        self.sub = self.create_subscription(String, 'output', self.on_output, 10)

    def on_output(self, msg: String) -> None:
        log = self.get_logger()
        log.debug(f'{msg.data} with DEBUG logger level.')
        log.info(f'{msg.data} with INFO logger level.')
        log.warning(f'{msg.data} with WARN logger level.')
        log.error(f'{msg.data} with ERROR logger level.')


class TestNode(Node):
    def __init__(self, remote_node_name: str, stop: threading.Event) -> None:
        super().__init__('TestNode')
        self.stop = stop
        self.remote = remote_node_name
        self.pub = self.create_publisher(String, 'output', 10)
        self.get_client = self.create_client(GetLoggerLevels,
                                             f'{remote_node_name}/get_logger_levels')
        self.set_client = self.create_client(SetLoggerLevels,
                                             f'{remote_node_name}/set_logger_levels')

    def set_remote_level(self, level: int) -> bool:
        if not self.set_client.service_is_ready():
            return False
        request = SetLoggerLevels.Request(levels=[LoggerLevel(name=self.remote, level=level)])
        future = self.set_client.call_async(request)
        if not spin_until_done(self, future, self.stop) or future.result() is None:
            return False
        result = future.result().results[0]
        if not result.successful:
            self.get_logger().error(f'Failed to change logger level: {result.reason}')
        return result.successful

    def log_remote_level(self) -> None:
        if self.get_client.service_is_ready():
            future = self.get_client.call_async(GetLoggerLevels.Request(names=[self.remote]))
            if spin_until_done(self, future, self.stop) and future.result() is not None:
                self.get_logger().info(f'Current logger level: {future.result().levels[0].level}')
                return
        self.get_logger().error('Failed to get logger level via logger service !')

    def output(self, text: str) -> None:
        self.pub.publish(String(data=text))
        time.sleep(0.5)  # the other node's thread logs it meanwhile


def run(test_node: TestNode) -> None:
    log = test_node.get_logger()
    for client in (test_node.get_client, test_node.set_client):
        client.wait_for_service(timeout_sec=SERVICE_WAIT)
    log.info('Output with default logger level:')
    test_node.output('Output 1')
    test_node.log_remote_level()
    for number, (name, level) in enumerate(
            (('debug', LoggingSeverity.DEBUG), ('warn', LoggingSeverity.WARN),
             ('error', LoggingSeverity.ERROR)), start=2):
        if test_node.stop.is_set():
            return
        log.info(f'Output with {name} logger level:')
        if test_node.set_remote_level(level):
            test_node.output(f'Output {number}')
        else:
            log.error(f'Failed to set {name} logger level via logger service !')
        test_node.log_remote_level()


def main() -> int:
    with ros_session() as stop:
        executor = SingleThreadedExecutor()
        executor.add_node(LoggerServiceNode())
        thread = threading.Thread(target=executor.spin, daemon=True)
        thread.start()
        test_node = TestNode('LoggerServiceNode', stop)
        # A subscription not yet matched would miss 'Output 1'.
        deadline = time.monotonic() + SERVICE_WAIT
        while test_node.pub.get_subscription_count() == 0 and time.monotonic() < deadline:
            time.sleep(0.05)
        run(test_node)
        executor.shutdown(timeout_sec=1.0)
        thread.join(timeout=2.0)
    return 0


if __name__ == '__main__':
    sys.exit(main())
