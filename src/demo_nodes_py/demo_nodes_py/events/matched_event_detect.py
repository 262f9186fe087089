"""`ros2 run demo_nodes_py matched_event_detect`: a node logs the matched events of its
publisher and its subscription while two helper nodes create and destroy subscriptions and
publishers on those topics, one at a time; then the program ends."""
from __future__ import annotations

import sys
import threading
import time

from node_runtime.spinning import SIGNAL_CHECK_PERIOD, ros_session
from rclpy.event_handler import (
    PublisherEventCallbacks,
    QoSPublisherMatchedInfo,
    QoSSubscriptionMatchedInfo,
    SubscriptionEventCallbacks,
)
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future
from std_msgs.msg import String

PUB_TOPIC = 'pub_topic_matched_event_detect'
SUB_TOPIC = 'sub_topic_matched_event_detect'
MAXIMUM_WAIT = 10.0  # seconds for each event


class MatchedEventDetectNode(Node):
    NAME = 'matched_event_detection_node'
    END = ''  # demo_nodes_cpp's lines end with a full stop

    def __init__(self) -> None:
        super().__init__(self.NAME)
        self.connected = {'subscription': False, 'publisher': False}
        self.future = Future()
        self.pub = self.create_publisher(String, PUB_TOPIC, 10, event_callbacks=(
            PublisherEventCallbacks(matched=lambda info: self.on_matched('subscription', info))))
        self.sub = self.create_subscription(
            String, SUB_TOPIC, lambda _msg: None, 10, event_callbacks=SubscriptionEventCallbacks(
                matched=lambda info: self.on_matched('publisher', info)))

    def on_matched(self, peer: str,
                   info: QoSPublisherMatchedInfo | QoSSubscriptionMatchedInfo) -> None:
        log = self.get_logger()
        if not self.connected[peer]:
            if info.current_count != 0:
                log.info(f'First {peer} is connected.')
                self.connected[peer] = True
        elif info.current_count == 0:
            log.info(f'Last {peer} is disconnected.')
            self.connected[peer] = False
        else:
            log.info(f'The changed number of connected {peer} is {info.current_count_change} '
                     f'and current number of connected {peer} is {info.current_count}{self.END}')
        self.future.set_result(True)

    def next_event(self) -> Future:
        self.future = Future()
        return self.future


class MultiSubNode(Node):
    def __init__(self) -> None:
        super().__init__('multi_sub_node')

    def create_one(self):
        self.get_logger().info('Create a new subscription.')
        return self.create_subscription(String, PUB_TOPIC, lambda _msg: None, 10)

    def destroy_one(self, sub) -> None:
        self.get_logger().info('Destroy a subscription.')
        self.destroy_subscription(sub)


class MultiPubNode(Node):
    def __init__(self) -> None:
        super().__init__('multi_pub_node')

    def create_one(self):
        self.get_logger().info('Create a new publisher.')
        return self.create_publisher(String, SUB_TOPIC, 10)

    def destroy_one(self, pub) -> None:
        self.get_logger().info('Destroy a publisher.')
        self.destroy_publisher(pub)


def run(detector: MatchedEventDetectNode, stop: threading.Event) -> None:
    subs, pubs = MultiSubNode(), MultiPubNode()
    executor = SingleThreadedExecutor()
    for node in (detector, subs, pubs):
        executor.add_node(node)

    def wait_for_event() -> None:
        future, deadline = detector.future, time.monotonic() + MAXIMUM_WAIT
        while not future.done() and not stop.is_set() and time.monotonic() < deadline:
            executor.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
        detector.next_event()

    for helper in (subs, pubs):  # subscriptions meet the publisher first, then the other way
        first = helper.create_one()
        wait_for_event()
        second = helper.create_one()
        wait_for_event()
        for entity in (first, second):
            if stop.is_set():
                return
            helper.destroy_one(entity)
            wait_for_event()
    executor.shutdown(timeout_sec=1.0)


def main(detector_class: type[MatchedEventDetectNode] = MatchedEventDetectNode) -> int:
    with ros_session() as stop:
        run(detector_class(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
