"""The server's one rclpy node, spun on its own thread, and the bridge to asyncio.

Everything that creates, uses or destroys a ROS entity runs on the executor's thread
(`RosBridge.run`); results come back to the web server's event loop as asyncio futures, and
messages that arrive are handed to it with call_soon_threadsafe.
"""

from __future__ import annotations

import asyncio
import threading
import time
from collections import deque
from collections.abc import Callable
from typing import Any

import rclpy
from rclpy.action import ActionClient
from rclpy.action.graph import (
    get_action_client_names_and_types_by_node,
    get_action_names_and_types,
    get_action_server_names_and_types_by_node,
)
from rclpy.context import Context
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, QoSProfile
from rclpy.signals import SignalHandlerOptions

from rqt_web.forms import interface_class

NODE_NAME = '_rqt_web'
GRAPH_PERIOD = 0.25  # seconds between graph polls while a page watches the graph
PUBLISHER_MATCH_WAIT = 1.0  # seconds a new publisher waits to match the known subscriptions
ROSOUT_KEEP = 5000  # log messages kept for pages opened later (rqt_console keeps 10000)
CANVAS_TYPE = 'std_msgs/msg/UInt8MultiArray'
# Reliable, volatile, keep-last unless said otherwise (QoSProfile's defaults).
ROSOUT_QOS = QoSProfile(depth=1000, durability=DurabilityPolicy.TRANSIENT_LOCAL)
CANVAS_QOS = QoSProfile(depth=1)  # the newest frame only
SEVERITY = {10: 'DEBUG', 20: 'INFO', 30: 'WARN', 40: 'ERROR', 50: 'FATAL'}


class RosBridge:
    def __init__(self, loop: asyncio.AbstractEventLoop) -> None:
        self.loop = loop
        self.context = Context()
        rclpy.init(args=[], context=self.context,
                   signal_handler_options=SignalHandlerOptions.NO)
        # Offers nothing to the graph (no parameter or type-description services).
        self.node = Node(NODE_NAME, context=self.context, start_parameter_services=False,
                         parameter_overrides=[Parameter('start_type_description_service',
                                                        value=False)])
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self._queue: deque[tuple[Callable[[], Any], asyncio.Future]] = deque()
        self._wake = self.node.create_guard_condition(self._run_queued)
        self._clients: dict[tuple[str, str], Any] = {}
        self._publishers: dict[tuple[str, str], Any] = {}
        self._action_clients: dict[tuple[str, str], ActionClient] = {}
        self._subscriptions: dict[tuple[str, str], tuple[Any, list[Callable]]] = {}
        # Graph watching: polled on the ROS thread only while some page listens.
        self.graph_listeners = 0
        self.on_graph: Callable[[dict], None] | None = None
        self.graph: dict | None = None
        self.node.create_timer(GRAPH_PERIOD, self._poll_graph)
        # /rosout from the start, so a console opened later shows what came before.
        self.log: deque[dict] = deque(maxlen=ROSOUT_KEEP)
        self.on_log: Callable[[dict], None] | None = None
        from rcl_interfaces.msg import Log
        self.node.create_subscription(Log, '/rosout', self._on_rosout, ROSOUT_QOS)
        self._thread = threading.Thread(target=self._spin, name='ros-spin', daemon=True)
        self._thread.start()

    # ---------------------------------------------------------------- thread plumbing
    def _spin(self) -> None:
        try:
            self.executor.spin()
        except (ExternalShutdownException, KeyboardInterrupt):
            pass

    def run(self, function: Callable[[], Any]) -> asyncio.Future:
        """Run `function` on the ROS thread; its result (or exception) as an asyncio future."""
        future = self.loop.create_future()
        self._queue.append((function, future))
        self._wake.trigger()
        return future

    def _run_queued(self) -> None:
        while self._queue:
            function, future = self._queue.popleft()
            try:
                result = function()
            except Exception as error:
                self.loop.call_soon_threadsafe(_settle, future, None, error)
            else:
                self.loop.call_soon_threadsafe(_settle, future, result, None)

    def to_asyncio(self, ros_future: Any) -> asyncio.Future:
        """An asyncio future completed with an rclpy future's result."""
        future = self.loop.create_future()

        def done(finished: Any) -> None:
            error = finished.exception()
            self.loop.call_soon_threadsafe(_settle, future, None if error else finished.result(),
                                           error)
        ros_future.add_done_callback(done)
        return future

    def shutdown(self) -> None:
        self.executor.shutdown(timeout_sec=1.0)
        self._thread.join(timeout=2.0)
        self.node.destroy_node()
        rclpy.try_shutdown(context=self.context)

    # ---------------------------------------------------------------- graph
    def _poll_graph(self) -> None:
        if self.graph_listeners <= 0 and self.graph is not None:
            return
        graph = self.snapshot()
        if graph != self.graph:
            self.graph = graph
            if self.on_graph is not None:
                self.loop.call_soon_threadsafe(self.on_graph, graph)

    def snapshot(self) -> dict:
        """Every node with its endpoints, as rqt_graph draws them (own node left out)."""
        node = self.node
        nodes = []
        for name, namespace in sorted(node.get_node_names_and_namespaces(),
                                      key=lambda n: (n[1], n[0])):
            full = namespace.rstrip('/') + '/' + name
            if full == node.get_fully_qualified_name():
                continue
            try:
                entry = {
                    'name': full,
                    'pubs': _pairs(node.get_publisher_names_and_types_by_node(name, namespace)),
                    'subs': _pairs(node.get_subscriber_names_and_types_by_node(name, namespace)),
                    'services': _pairs(node.get_service_names_and_types_by_node(name, namespace)),
                    'action_servers': _pairs(
                        get_action_server_names_and_types_by_node(node, name, namespace)),
                    'action_clients': _pairs(
                        get_action_client_names_and_types_by_node(node, name, namespace)),
                }
            except Exception:  # the node left between listing and asking: next poll
                continue
            nodes.append(entry)
        return {'nodes': nodes,
                'topics': _pairs(node.get_topic_names_and_types()),
                'services': _pairs(node.get_service_names_and_types()),
                'actions': _pairs(get_action_names_and_types(node))}

    # ---------------------------------------------------------------- console
    def _on_rosout(self, msg: Any) -> None:
        entry = {'stamp': msg.stamp.sec + msg.stamp.nanosec * 1e-9,
                 'severity': SEVERITY.get(msg.level, str(msg.level)), 'level': msg.level,
                 'node': msg.name, 'message': msg.msg, 'file': msg.file,
                 'function': msg.function, 'line': msg.line}
        self.log.append(entry)
        if self.on_log is not None:
            self.loop.call_soon_threadsafe(self.on_log, entry)

    # ---------------------------------------------------------------- services
    async def call_service(self, name: str, srv_type: str, request: Any,
                           timeout: float) -> Any:
        """The response, or TimeoutError when the service is absent or does not answer."""
        srv_class = interface_class(srv_type, 'srv')
        key = (name, srv_type)

        def client() -> Any:
            if key not in self._clients:
                self._clients[key] = self.node.create_client(srv_class, name)
            return self._clients[key]
        service_client = await self.run(client)
        deadline = time.monotonic() + timeout
        while not service_client.service_is_ready():
            if time.monotonic() > deadline:
                raise TimeoutError(f'service {name} is not available')
            await asyncio.sleep(0.02)
        pending = await self.run(lambda: service_client.call_async(request))
        try:
            return await asyncio.wait_for(self.to_asyncio(pending),
                                          max(0.05, deadline - time.monotonic()))
        except asyncio.TimeoutError:
            self.run(lambda: service_client.remove_pending_request(pending))
            raise TimeoutError(f'service {name} did not answer within {timeout:g} s') from None

    # ---------------------------------------------------------------- topics
    async def publish(self, topic: str, msg_type: str, msg: Any) -> None:
        msg_class = interface_class(msg_type, 'msg')
        key = (topic, msg_type)

        def publisher() -> tuple[Any, bool]:
            fresh = key not in self._publishers
            if fresh:
                self._publishers[key] = self.node.create_publisher(msg_class, topic, 10)
            return self._publishers[key], fresh

        created, fresh = await self.run(publisher)
        if fresh:
            # A new publisher's first message is lost by every subscription it has not matched
            # yet (volatile): wait, briefly, until it matched those the graph already shows.
            deadline = time.monotonic() + PUBLISHER_MATCH_WAIT
            while time.monotonic() < deadline:
                known = await self.run(lambda: self.node.count_subscribers(topic))
                if created.get_subscription_count() >= known:
                    break
                await asyncio.sleep(0.02)
        await self.run(lambda: created.publish(msg))

    async def subscribe(self, topic: str, msg_type: str, callback: Callable[[Any], None],
                        raw: bool = False, qos: Any = 10) -> None:
        """Share one subscription per (topic, type) among callbacks (called on the loop)."""
        key = (topic, msg_type)

        def add() -> None:
            if key in self._subscriptions:
                self._subscriptions[key][1].append(callback)
                return
            callbacks = [callback]

            def received(msg: Any) -> None:
                for each in list(callbacks):
                    self.loop.call_soon_threadsafe(each, msg)
            subscription = self.node.create_subscription(
                interface_class(msg_type, 'msg'), topic, received, qos, raw=raw)
            self._subscriptions[key] = (subscription, callbacks)
        await self.run(add)

    async def unsubscribe(self, topic: str, msg_type: str, callback: Callable) -> None:
        key = (topic, msg_type)

        def remove() -> None:
            entry = self._subscriptions.get(key)
            if entry is None or callback not in entry[1]:
                return
            entry[1].remove(callback)
            if not entry[1]:
                self.node.destroy_subscription(entry[0])
                del self._subscriptions[key]
        await self.run(remove)

    # ---------------------------------------------------------------- actions
    async def action_client(self, name: str, action_type: str) -> ActionClient:
        key = (name, action_type)

        def create() -> ActionClient:
            if key not in self._action_clients:
                self._action_clients[key] = ActionClient(
                    self.node, interface_class(action_type, 'action'), name)
            return self._action_clients[key]
        return await self.run(create)


def _pairs(names_and_types: list) -> list[list]:
    return sorted([name, list(types)] for name, types in names_and_types)


def _settle(future: asyncio.Future, result: Any, error: BaseException | None) -> None:
    if future.done():
        return
    if error is not None:
        future.set_exception(error)
    else:
        future.set_result(result)
