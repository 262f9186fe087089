"""The ROS side of the bridge: graph, raw subscriptions, client publishers, services, time.

One rclpy node, spun on its own thread. The WebSocket front-ends (one per subprotocol) call
its methods from their threads; it calls them back through the `Frontend` protocol. Topic
payloads stay CDR bytes from DDS to the socket (`raw=True`), and client-published CDR goes
to DDS as it came; client-published JSON (upstream's other encoding) is converted first.
"""

from __future__ import annotations

import concurrent.futures
import json
import os
import queue
import threading
import time
from collections.abc import Hashable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

from ament_index_python import PackageNotFoundError, get_package_share_directory
from rclpy.exceptions import InvalidHandle
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rclpy.serialization import deserialize_message, serialize_message
from rosgraph_msgs.msg import Clock
from rosidl_runtime_py.set_message import FieldError

from foxglove_bridge.definitions import DefinitionNotFound, full_text, interface_class
from foxglove_bridge.parameters import Settings, allowed, declare_settings
from foxglove_bridge.ros_parameters import ParameterAccess
from rosidl_runtime_py import set_message_fields

GRAPH_PERIOD = 1.0  # seconds between graph polls (new topics and services show up this late)
SERVICE_TIMEOUT = 5.0  # seconds a client's service call may take
JOB_TIMEOUT = 5.0  # seconds a front-end waits for the ROS thread to create or destroy
CLIENT_ENCODINGS = ('cdr', 'json')  # what clients may publish in (upstream Jazzy's two)


class BridgeError(Exception):
    """A client request the bridge refuses; the message goes to that client as it is."""


@dataclass(frozen=True)
class ChannelInfo:
    id: int
    topic: str
    type: str
    schema: str


@dataclass(frozen=True)
class ServiceInfo:
    id: int
    name: str
    type: str
    request_schema: str
    response_schema: str


@dataclass
class Graph:
    published: dict[str, set[str]] = field(default_factory=dict)
    subscribed: dict[str, set[str]] = field(default_factory=dict)
    services: dict[str, set[str]] = field(default_factory=dict)


class Frontend(Protocol):
    def channels_changed(self, added: list[ChannelInfo], removed: list[int]) -> None: ...
    def services_changed(self, added: list[ServiceInfo], removed: list[int]) -> None: ...
    def message(self, channel_id: int, stamp_ns: int, data: bytes) -> None: ...
    def parameters_changed(self, values: list[dict[str, Any]]) -> None: ...
    def graph_changed(self, graph: Graph) -> None: ...
    def time(self, stamp_ns: int) -> None: ...


def hidden(name: str) -> bool:
    return any(part.startswith('_') for part in name.split('/'))


@dataclass
class ClientPublisher:
    topic: str
    msg_class: Any
    publisher: Any
    encoding: str


class FoxgloveBridge(Node):
    def __init__(self) -> None:
        super().__init__('foxglove_bridge')
        self.settings: Settings = declare_settings(self)
        self.frontends: list[Frontend] = []
        self._bridge_lock = threading.RLock()
        self._entity_lock = threading.Lock()
        self._jobs: queue.SimpleQueue[Any] = queue.SimpleQueue()
        self._ros_thread: int | None = None
        self._wake = self.create_guard_condition(self._on_jobs)
        self._next_id = 1
        self.channels: dict[int, ChannelInfo] = {}
        self._channel_ids: dict[tuple[str, str], int] = {}
        self.service_infos: dict[int, ServiceInfo] = {}
        self._service_ids: dict[tuple[str, str], int] = {}
        self._service_clients: dict[int, Any] = {}
        self._reader_holders: dict[int, set[Hashable]] = {}
        self._readers: dict[int, Any] = {}
        self._client_pubs: dict[Hashable, ClientPublisher] = {}
        self._missing_types: set[str] = set()
        self._graph_watchers: set[Hashable] = set()
        self._last_graph: Graph | None = None
        self.params = ParameterAccess(self, self.settings.param_whitelist, self._parameters_changed)
        if self.settings.use_sim_time:
            self.create_subscription(Clock, '/clock', self._on_clock, 10)
        self.create_timer(GRAPH_PERIOD, self._on_graph_timer)

    # --- graph ---------------------------------------------------------------------------

    def poll_graph(self) -> None:
        self._update_channels()
        if 'services' in self.settings.capabilities:
            self._update_services()
        if self._graph_watchers:
            self._publish_graph(force=False)

    def _on_graph_timer(self) -> None:
        self._ros_thread = threading.get_ident()
        self.poll_graph()

    def _visible(self, name: str, whitelist: list[Any]) -> bool:
        return (self.settings.include_hidden or not hidden(name)) and allowed(whitelist, name)

    def _schema(self, type_name: str) -> str | None:
        try:
            return full_text(type_name)
        except DefinitionNotFound:
            if type_name not in self._missing_types:
                self._missing_types.add(type_name)
                self.get_logger().warn(f'Could not find definition for type {type_name}')
            return None

    def _update_channels(self) -> None:
        present = set()
        for topic, types in self.get_topic_names_and_types():
            if not self._visible(topic, self.settings.topic_whitelist):
                continue
            present.update((topic, type_name) for type_name in types)
        added, removed = [], []
        with self._bridge_lock:
            for key in sorted(present - set(self._channel_ids)):
                schema = self._schema(key[1])
                if schema is None:
                    continue
                info = ChannelInfo(self._take_id(), key[0], key[1], schema)
                self._channel_ids[key] = info.id
                self.channels[info.id] = info
                added.append(info)
            for key in set(self._channel_ids) - present:
                channel_id = self._channel_ids.pop(key)
                del self.channels[channel_id]
                self._drop_subscription(channel_id)
                self._reader_holders.pop(channel_id, None)
                removed.append(channel_id)
        if added or removed:
            for frontend in self.frontends:
                frontend.channels_changed(added, removed)

    def _update_services(self) -> None:
        present = set()
        for name, types in self.get_service_names_and_types():
            if self._visible(name, self.settings.service_whitelist):
                present.update((name, type_name) for type_name in types)
        added, removed = [], []
        with self._bridge_lock:
            for key in sorted(present - set(self._service_ids)):
                request = self._schema(key[1] + '_Request')
                response = self._schema(key[1] + '_Response')
                if request is None or response is None:
                    continue
                info = ServiceInfo(self._take_id(), key[0], key[1], request, response)
                self._service_ids[key] = info.id
                self.service_infos[info.id] = info
                added.append(info)
            for key in set(self._service_ids) - present:
                service_id = self._service_ids.pop(key)
                del self.service_infos[service_id]
                client = self._service_clients.pop(service_id, None)
                if client is not None:
                    self.destroy_client(client)
                removed.append(service_id)
        if added or removed:
            for frontend in self.frontends:
                frontend.services_changed(added, removed)

    def _take_id(self) -> int:
        self._next_id += 1
        return self._next_id - 1

    # --- subscriptions: a DDS reader only while some client subscribes ----------------------

    # rclpy entities are created and destroyed on the executor's thread only: a subscription
    # destroyed from another thread while the executor built its wait set raised InvalidHandle
    # there and stopped the executor (seen with 200 topics). Front-ends queue the work
    # (on_ros_thread); _entity_lock, never taken on the executor thread, orders them.

    def on_ros_thread(self, function: Any, *args: Any) -> Any:
        if threading.get_ident() == self._ros_thread:
            return function(*args)
        job: concurrent.futures.Future[Any] = concurrent.futures.Future()
        self._jobs.put((job, function, args))
        try:
            self._wake.trigger()
        except InvalidHandle:
            # Ctrl-C while a client still subscribes: ROS shut down first and took the node's
            # entities with it, so the client's release has nothing left to undo.
            return None
        try:
            return job.result(timeout=JOB_TIMEOUT)
        except concurrent.futures.TimeoutError:
            raise BridgeError(f'ROS side did not answer within {JOB_TIMEOUT} s') from None

    def _on_jobs(self) -> None:
        self._ros_thread = threading.get_ident()
        while True:
            try:
                job, function, args = self._jobs.get_nowait()
            except queue.Empty:
                return
            if job.set_running_or_notify_cancel():
                try:
                    job.set_result(function(*args))
                except Exception as error:  # handed to the waiting front-end
                    job.set_exception(error)

    def subscribe(self, channel_id: int, subscriber: Hashable) -> None:
        with self._entity_lock:
            with self._bridge_lock:
                info = self.channels.get(channel_id)
                if info is None:
                    raise BridgeError(f'Unknown channel ID: {channel_id}')
                self._reader_holders.setdefault(channel_id, set()).add(subscriber)
                if channel_id in self._readers:
                    return
            reader = self.on_ros_thread(lambda: self.create_subscription(
                interface_class(info.type), info.topic,
                lambda data, cid=channel_id: self._on_message(cid, data),
                self._subscription_qos(info.topic), raw=True))
            with self._bridge_lock:
                self._readers[channel_id] = reader
            self.get_logger().info(f"Subscribing to topic '{info.topic}' ({info.type})")

    def unsubscribe(self, channel_id: int, subscriber: Hashable) -> None:
        with self._entity_lock:
            with self._bridge_lock:
                holders = self._reader_holders.get(channel_id)
                if holders is None:
                    return
                holders.discard(subscriber)
                if holders:
                    return
                del self._reader_holders[channel_id]
                reader = self._readers.pop(channel_id, None)
                info = self.channels.get(channel_id)
            if reader is not None:
                self.on_ros_thread(self.destroy_subscription, reader)
                self.get_logger().info(f"Unsubscribing from topic '{info.topic if info else '?'}'")

    def _drop_subscription(self, channel_id: int) -> None:
        """On the executor thread (graph timer): the topic is gone."""
        reader = self._readers.pop(channel_id, None)
        if reader is not None:
            self.destroy_subscription(reader)

    def subscription_count(self) -> int:
        with self._bridge_lock:
            return len(self._readers)

    def _subscription_qos(self, topic: str) -> QoSProfile:
        """Upstream's choice: depth from the publishers' (clamped), their reliability/durability."""
        publishers = self.get_publishers_info_by_topic(topic)
        depth = sum(max(p.qos_profile.depth, 1) for p in publishers) or 1
        depth = min(max(depth, self.settings.min_qos_depth), self.settings.max_qos_depth)
        qos = QoSProfile(depth=max(depth, 1))
        if any(p.qos_profile.reliability == ReliabilityPolicy.BEST_EFFORT for p in publishers):
            qos.reliability = ReliabilityPolicy.BEST_EFFORT
        if publishers and all(p.qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL
                              for p in publishers):
            qos.durability = DurabilityPolicy.TRANSIENT_LOCAL
        return qos

    def _on_message(self, channel_id: int, data: bytes) -> None:
        stamp = time.time_ns()
        for frontend in self.frontends:
            frontend.message(channel_id, stamp, data)

    # --- client publish -------------------------------------------------------------------

    def client_advertise(self, key: Hashable, topic: str, encoding: str,
                         schema_name: str) -> None:
        if 'clientPublish' not in self.settings.capabilities:
            raise BridgeError('Server does not support clientPublish capability')
        if encoding not in CLIENT_ENCODINGS:
            raise BridgeError(f"Unsupported encoding '{encoding}' for topic '{topic}': "
                              "this bridge accepts 'cdr' and 'json'")
        if not allowed(self.settings.client_topic_whitelist, topic):
            raise BridgeError(f"Topic '{topic}' is not whitelisted (client_topic_whitelist)")
        type_name = schema_name if schema_name.count('/') == 2 else schema_name.replace(
            '/', '/msg/', 1)
        try:
            msg_class = interface_class(type_name)
        except DefinitionNotFound:
            raise BridgeError(f"Unknown message type '{schema_name}' for topic '{topic}'") from None
        with self._entity_lock:
            if key in self._client_pubs:
                raise BridgeError(f"Client channel for topic '{topic}' is already advertised")
            publisher = self.on_ros_thread(self.create_publisher, msg_class, topic, 10)
            self._client_pubs[key] = ClientPublisher(topic, msg_class, publisher, encoding)
        self.get_logger().info(f"Client advertised topic '{topic}' ({type_name})")

    def client_unadvertise(self, key: Hashable) -> None:
        with self._entity_lock:
            entry = self._client_pubs.pop(key, None)
            if entry is not None:
                self.on_ros_thread(self.destroy_publisher, entry.publisher)

    def client_publish(self, key: Hashable, data: bytes) -> None:
        entry = self._client_pubs.get(key)
        if entry is None:
            raise BridgeError('Unknown client channel: advertise it first')
        if entry.encoding == 'json':
            entry.publisher.publish(self._from_json(entry, data))
            return
        try:
            # Checked, not converted: what goes to DDS are the client's own CDR bytes.
            deserialize_message(data, entry.msg_class)
        except Exception:
            raise BridgeError(f"Message for '{entry.topic}' is not valid CDR of "
                              f'{entry.msg_class.__module__}/{entry.msg_class.__name__}') from None
        entry.publisher.publish(data)

    @staticmethod
    def _from_json(entry: ClientPublisher, data: bytes) -> Any:
        """The message a JSON object (field names to values, as upstream's parser takes) gives;
        BridgeError naming the field when it does not fit the type."""
        try:
            values = json.loads(data)
        except (ValueError, RecursionError) as error:
            raise BridgeError(f"Message for '{entry.topic}' is not valid JSON: {error}") from None
        message = entry.msg_class()
        try:
            set_message_fields(message, values)
        except (FieldError, RecursionError) as error:
            raise BridgeError(f"Message for '{entry.topic}' does not fit "
                              f'{entry.msg_class.__module__}/{entry.msg_class.__name__}: '
                              f'{error}') from None
        return message

    # --- services -------------------------------------------------------------------------

    def call_service(self, service_id: int, encoding: str, payload: bytes) -> bytes:
        """Blocking: call from a front-end's worker thread, never from the executor's."""
        info = self.service_infos.get(service_id)
        if info is None:
            raise BridgeError(f'Unknown service ID: {service_id}')
        if encoding != 'cdr':
            raise BridgeError(f"Unsupported encoding '{encoding}': this bridge accepts 'cdr'")
        srv_class = interface_class(info.type)
        try:
            # rclpy has no raw service client: deserialize with rclpy's CDR, call, serialize.
            request = deserialize_message(payload, srv_class.Request)
        except Exception:
            raise BridgeError(f"Request is not valid CDR of {info.type}_Request") from None
        with self._entity_lock:
            client = self._service_clients.get(service_id)
            if client is None:
                client = self.on_ros_thread(self.create_client, srv_class, info.name)
                self._service_clients[service_id] = client
        if not client.wait_for_service(timeout_sec=SERVICE_TIMEOUT):
            raise BridgeError(f"Service '{info.name}' is not available")
        done = threading.Event()
        future = client.call_async(request)
        future.add_done_callback(lambda _future: done.set())
        if not done.wait(SERVICE_TIMEOUT):
            client.remove_pending_request(future)
            raise BridgeError(f"Service '{info.name}' did not answer within {SERVICE_TIMEOUT} s")
        if future.exception() is not None:
            raise BridgeError(f"Service '{info.name}' failed: {future.exception()}")
        return serialize_message(future.result())

    # --- parameters, graph, time, assets --------------------------------------------------

    def _parameters_changed(self, values: list[dict[str, Any]]) -> None:
        for frontend in self.frontends:
            frontend.parameters_changed(values)

    def watch_graph(self, watcher: Hashable, on: bool) -> None:
        with self._bridge_lock:
            (self._graph_watchers.add if on else self._graph_watchers.discard)(watcher)
        if on:
            self._last_graph = None  # a new watcher gets the whole graph at the next poll

    def _publish_graph(self, force: bool) -> None:
        graph = Graph()
        for name, namespace in self.get_node_names_and_namespaces():
            node = f"{namespace.rstrip('/')}/{name}"
            for getter, target in (
                    (self.get_publisher_names_and_types_by_node, graph.published),
                    (self.get_subscriber_names_and_types_by_node, graph.subscribed),
                    (self.get_service_names_and_types_by_node, graph.services)):
                try:
                    entries = getter(name, namespace)
                except Exception:  # the node left between the two calls
                    continue
                for topic, _types in entries:
                    target.setdefault(topic, set()).add(node)
        if force or graph != self._last_graph:
            self._last_graph = graph
            for frontend in self.frontends:
                frontend.graph_changed(graph)

    def current_graph(self) -> Graph:
        return self._last_graph or Graph()

    def _on_clock(self, msg: Clock) -> None:
        stamp = msg.clock.sec * 1_000_000_000 + msg.clock.nanosec
        for frontend in self.frontends:
            frontend.time(stamp)

    def fetch_asset(self, uri: str) -> bytes:
        if not allowed(self.settings.asset_uri_allowlist, uri):
            raise BridgeError(f"Asset URI not allowed: {uri}")
        if not uri.startswith('package://'):
            raise BridgeError(f"Unsupported asset URI (package:// only): {uri}")
        package, _, relative = uri[len('package://'):].partition('/')
        try:
            root = Path(os.path.normpath(get_package_share_directory(package)))
        except (PackageNotFoundError, ValueError):
            raise BridgeError(f"Package '{package}' not found for asset {uri}") from None
        # Normalised, not resolved: a --symlink-install share links its files to src/.
        path = Path(os.path.normpath(root / relative))
        if root not in path.parents or not path.is_file():
            raise BridgeError(f'Asset not found: {uri}')
        return path.read_bytes()
