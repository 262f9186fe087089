"""`foxglove.sdk.v1`: the foxglove-sdk's own WebSocket server, fed by the ROS side.

The SDK's server (Rust, in the `foxglove-sdk` wheel) owns its listening socket and speaks
only `foxglove.sdk.v1`, so it listens on an ephemeral loopback port and the bridge's port
forwards the connections that ask for that subprotocol to it (front.py).
"""

from __future__ import annotations

import base64
import threading
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import foxglove
from foxglove import Context, Schema
from foxglove.websocket import (
    Capability,
    ChannelView,
    Client,
    ClientChannel,
    ConnectionGraph,
    MessageSchema,
    Parameter,
    ParameterType,
    Service,
    ServiceRequest,
    ServiceSchema,
    StatusLevel,
)

from foxglove_bridge.ros_bridge import (
    CLIENT_ENCODINGS,
    BridgeError,
    ChannelInfo,
    FoxgloveBridge,
    Graph,
    ServiceInfo,
)
from foxglove_bridge.ros_parameters import ParameterError
from foxglove_bridge.sdk_log import route_sdk_logs

CAPABILITIES = {'clientPublish': Capability.ClientPublish, 'parameters': Capability.Parameters,
                'services': Capability.Services, 'connectionGraph': Capability.ConnectionGraph}
HINTS = {'float64': ParameterType.Float64, 'float64_array': ParameterType.Float64Array,
         'byte_array': ParameterType.ByteArray}


def sdk_parameter(entry: dict[str, Any]) -> Parameter:
    hint = entry.get('type')
    if hint == 'byte_array':
        return Parameter(entry['name'], value=base64.b64decode(entry['value']))
    return Parameter(entry['name'], value=entry['value'], type=HINTS.get(hint))


class SdkServer:
    """Implements the SDK's ServerListener and the bridge's Frontend protocol."""

    def __init__(self, ros: FoxgloveBridge, session_id: str) -> None:
        self.ros = ros
        self.context = Context()
        self._lock = threading.Lock()
        self._channels: dict[int, Any] = {}   # our channel id -> SDK BaseChannel
        self._ours: dict[int, int] = {}       # SDK channel id -> our channel id
        self._service_names: dict[int, str] = {}
        # Subscribes run here, in order, not on the SDK's thread: the SDK may hold its channel
        # state while calling us, and the ROS thread needs it for channel.log meanwhile.
        self._worker = ThreadPoolExecutor(max_workers=1, thread_name_prefix='sdk_subscribe')
        route_sdk_logs(ros.get_logger())
        capabilities = [CAPABILITIES[c] for c in ros.settings.capabilities if c in CAPABILITIES]
        if ros.settings.use_sim_time:
            capabilities.append(Capability.Time)
        self.server = foxglove.start_server(
            name='foxglove_bridge', host='127.0.0.1', port=0, capabilities=capabilities,
            server_listener=self, supported_encodings=list(CLIENT_ENCODINGS), context=self.context,
            session_id=session_id,
            asset_handler=self._asset if 'assets' in ros.settings.capabilities else None)
        self.port = self.server.port

    def stop(self) -> None:
        self.server.stop()
        self._worker.shutdown(wait=False, cancel_futures=True)

    def _status(self, message: str) -> None:
        self.ros.get_logger().warn(message)
        self.server.publish_status(message, StatusLevel.Error)

    # --- Frontend (called from the ROS thread) ----------------------------------------------

    def channels_changed(self, added: list[ChannelInfo], removed: list[int]) -> None:
        with self._lock:
            for channel_id in removed:
                channel = self._channels.pop(channel_id, None)
                if channel is not None:
                    self._ours.pop(channel.id(), None)
                    channel.close()
            for info in added:
                channel = self.context._create_channel(
                    info.topic, message_encoding='cdr',
                    schema=Schema(name=info.type, encoding='ros2msg', data=info.schema.encode()),
                    metadata=None)
                self._channels[info.id] = channel
                self._ours[channel.id()] = info.id

    def services_changed(self, added: list[ServiceInfo], removed: list[int]) -> None:
        if 'services' not in self.ros.settings.capabilities:
            return
        names = [self._service_names.pop(i) for i in removed if i in self._service_names]
        if names:
            self.server.remove_services(names)
        services = []
        for info in added:
            def half(suffix: str, text: str, info: ServiceInfo = info) -> MessageSchema:
                return MessageSchema(encoding='cdr', schema=Schema(
                    name=info.type + suffix, encoding='ros2msg', data=text.encode()))
            services.append(Service(info.name, schema=ServiceSchema(
                info.type, request=half('_Request', info.request_schema),
                response=half('_Response', info.response_schema)),
                handler=lambda request, sid=info.id: self._call(sid, request)))
            self._service_names[info.id] = info.name
        if services:
            self.server.add_services(services)

    def message(self, channel_id: int, stamp_ns: int, data: bytes) -> None:
        channel = self._channels.get(channel_id)
        if channel is not None:
            channel.log(data, log_time=stamp_ns)

    def parameters_changed(self, values: list[dict[str, Any]]) -> None:
        self.server.publish_parameter_values([sdk_parameter(v) for v in values])

    def graph_changed(self, graph: Graph) -> None:
        update = ConnectionGraph()
        for topic, ids in graph.published.items():
            update.set_published_topic(topic, sorted(ids))
        for topic, ids in graph.subscribed.items():
            update.set_subscribed_topic(topic, sorted(ids))
        for service, ids in graph.services.items():
            update.set_advertised_service(service, sorted(ids))
        self.server.publish_connection_graph(update)

    def time(self, stamp_ns: int) -> None:
        self.server.broadcast_time(stamp_ns)

    # --- ServerListener (called from the SDK's threads) -------------------------------------

    def on_subscribe(self, client: Client, channel: ChannelView) -> None:
        ours = self._ours.get(channel.id)
        if ours is not None:
            self._worker.submit(self._quietly, self.ros.subscribe, ours, ('sdk', client.id))

    def on_unsubscribe(self, client: Client, channel: ChannelView) -> None:
        ours = self._ours.get(channel.id)
        if ours is not None:
            self._worker.submit(self._quietly, self.ros.unsubscribe, ours, ('sdk', client.id))

    def _quietly(self, function: Any, *args: Any) -> None:
        try:
            function(*args)
        except BridgeError as error:
            self._status(str(error))

    def on_client_advertise(self, client: Client, channel: ClientChannel) -> None:
        try:
            self.ros.client_advertise(('sdk', client.id, channel.id), channel.topic,
                                      channel.encoding, channel.schema_name)
        except BridgeError as error:
            self._status(str(error))

    def on_client_unadvertise(self, client: Client, client_channel_id: int) -> None:
        self.ros.client_unadvertise(('sdk', client.id, client_channel_id))

    def on_message_data(self, client: Client, client_channel_id: int, data: bytes) -> None:
        try:
            self.ros.client_publish(('sdk', client.id, client_channel_id), data)
        except BridgeError as error:
            self._status(str(error))

    def on_get_parameters(self, client: Client, param_names: list[str],
                          request_id: str | None = None) -> list[Parameter]:
        try:
            return [sdk_parameter(v) for v in self.ros.params.get(list(param_names))]
        except ParameterError as error:
            self._status(str(error))
            return []

    def on_set_parameters(self, client: Client, parameters: list[Parameter],
                          request_id: str | None = None) -> list[Parameter]:
        items = [(p.name, p.get_value(), next((k for k, v in HINTS.items() if v == p.type), None))
                 for p in parameters]
        items = [(name, base64.b64encode(value).decode(), 'byte_array')
                 if isinstance(value, bytes) else (name, value, hint)
                 for name, value, hint in items]
        try:
            return [sdk_parameter(v) for v in self.ros.params.set(items)]
        except ParameterError as error:
            self._status(str(error))
            return []

    def on_parameters_subscribe(self, param_names: list[str]) -> None:
        self.ros.params.watch(('sdk',), list(param_names), True)

    def on_parameters_unsubscribe(self, param_names: list[str]) -> None:
        self.ros.params.watch(('sdk',), list(param_names), False)

    def on_connection_graph_subscribe(self) -> None:
        # The SDK sends the current graph itself; the next poll publishes ours.
        self.ros.watch_graph(('sdk',), True)

    def on_connection_graph_unsubscribe(self) -> None:
        self.ros.watch_graph(('sdk',), False)

    def _call(self, service_id: int, request: ServiceRequest) -> bytes:
        try:
            return self.ros.call_service(service_id, request.encoding, request.payload)
        except BridgeError as error:
            raise RuntimeError(str(error)) from None

    def _asset(self, uri: str) -> bytes | None:
        try:
            return self.ros.fetch_asset(uri)
        except BridgeError as error:
            self.ros.get_logger().warn(str(error))
            return None
