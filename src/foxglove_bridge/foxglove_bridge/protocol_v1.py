"""`foxglove.websocket.v1`: the Foxglove WebSocket protocol, served on the `websockets` library.

Older Lichtblick and @foxglove/ws-protocol's client speak only this subprotocol (Lichtblick
1.28 offers `foxglove.sdk.v1` beside it and is served that); foxglove-sdk 0.30.3's
server refuses it (HTTP 400), so the bridge serves it itself. JSON text frames for control,
binary frames (little-endian, one opcode byte first) for data, as in ws-protocol's spec.
"""

from __future__ import annotations

import asyncio
import collections
import json
import struct
import threading
import time
from typing import Any

from websockets.asyncio.server import ServerConnection, serve
from websockets.exceptions import ConnectionClosed

from foxglove_bridge.ros_bridge import (
    CLIENT_ENCODINGS,
    BridgeError,
    ChannelInfo,
    FoxgloveBridge,
    Graph,
    ServiceInfo,
)
from foxglove_bridge.ros_parameters import ParameterError

SUBPROTOCOL = 'foxglove.websocket.v1'
MAX_CLIENT_MESSAGE = 16 * 1024 * 1024  # bytes; larger frames close the connection (1009)
# Server binary opcodes
MESSAGE_DATA, TIME, SERVICE_CALL_RESPONSE, FETCH_ASSET_RESPONSE = 1, 2, 3, 4
# Client binary opcodes
CLIENT_MESSAGE_DATA, CLIENT_SERVICE_CALL_REQUEST = 1, 2
ERROR, WARNING, INFO = 2, 1, 0
BATCH = 256  # frames written per drain


def channel_json(info: ChannelInfo) -> dict[str, Any]:
    return {'id': info.id, 'topic': info.topic, 'encoding': 'cdr', 'schemaName': info.type,
            'schema': info.schema, 'schemaEncoding': 'ros2msg'}


def service_json(info: ServiceInfo) -> dict[str, Any]:
    def half(suffix: str, schema: str) -> dict[str, str]:
        return {'encoding': 'cdr', 'schemaName': info.type + suffix,
                'schemaEncoding': 'ros2msg', 'schema': schema}
    return {'id': info.id, 'name': info.name, 'type': info.type,
            'requestSchema': info.request_schema, 'responseSchema': info.response_schema,
            'request': half('_Request', info.request_schema),
            'response': half('_Response', info.response_schema)}


def graph_json(graph: Graph, previous: Graph) -> dict[str, Any]:
    return {'op': 'connectionGraphUpdate',
            'publishedTopics': [{'name': t, 'publisherIds': sorted(ids)}
                                for t, ids in sorted(graph.published.items())],
            'subscribedTopics': [{'name': t, 'subscriberIds': sorted(ids)}
                                 for t, ids in sorted(graph.subscribed.items())],
            'advertisedServices': [{'name': s, 'providerIds': sorted(ids)}
                                   for s, ids in sorted(graph.services.items())],
            'removedTopics': sorted((set(previous.published) | set(previous.subscribed))
                                    - set(graph.published) - set(graph.subscribed)),
            'removedServices': sorted(set(previous.services) - set(graph.services))}


class Client:
    """One connection: its subscriptions, advertised channels and an outgoing queue."""

    def __init__(self, server: V1Server, connection: ServerConnection, number: int) -> None:
        self.server = server
        self.connection = connection
        self.number = number
        self.subscriptions: dict[int, int] = {}   # subscription id -> channel id
        self.by_channel: dict[int, int] = {}      # channel id -> subscription id
        self.advertised: set[int] = set()         # client channel ids
        self.params: set[str] = set()
        self.graph: Graph | None = None
        self.queue: collections.deque[str | bytes] = collections.deque()
        self.queued_bytes = 0
        self.wake = asyncio.Event()
        self.dropped = 0
        self.calls: set[asyncio.Task[None]] = set()

    def key(self, suffix: object = None) -> tuple[object, ...]:
        return ('v1', self.number, suffix)

    def send(self, message: str | bytes | dict[str, Any], droppable: bool = False) -> None:
        """Queue a frame; data frames are dropped past send_buffer_limit (upstream's rule)."""
        if isinstance(message, dict):
            message = json.dumps(message)
        size = len(message)
        if droppable:
            transport = self.connection.transport
            buffered = transport.get_write_buffer_size() if transport else 0
            if self.queued_bytes + buffered + size > self.server.ros.settings.send_buffer_limit:
                self.dropped += 1
                return
        self.queue.append(message)
        self.queued_bytes += size
        self.wake.set()

    def status(self, level: int, message: str) -> None:
        self.send({'op': 'status', 'level': level, 'message': message})

    async def sender(self) -> None:
        # Up to BATCH frames per write and drain: connection.send() awaits once per frame,
        # which kept up with 1 client but not with 5 at 12,500 msg/s each (bench/foxglove.py).
        # send_context() + the Sans-I/O protocol is how websockets' own send() writes a frame.
        connection = self.connection
        while True:
            await self.wake.wait()
            self.wake.clear()
            while self.queue:
                async with connection.send_context():
                    for _ in range(min(BATCH, len(self.queue))):
                        message = self.queue.popleft()
                        self.queued_bytes -= len(message)
                        if isinstance(message, str):
                            connection.protocol.send_text(message.encode())
                        else:
                            connection.protocol.send_binary(message)


class V1Server:
    """The foxglove.websocket.v1 server, on the asyncio loop of the calling thread."""

    def __init__(self, ros: FoxgloveBridge, session_id: str) -> None:
        self.ros = ros
        self.session_id = session_id
        self.clients: dict[int, Client] = {}
        self._numbers = 0
        self.loop: asyncio.AbstractEventLoop | None = None
        self._pending: collections.deque[tuple[int, int, bytes]] = collections.deque()
        self._scheduled = False
        self._pending_lock = threading.Lock()
        self.port = 0
        self.capabilities = [c for c in ros.settings.capabilities if c != 'time']
        if ros.settings.use_sim_time:
            self.capabilities.append('time')

    async def start(self) -> Any:
        self.loop = asyncio.get_running_loop()
        server = await serve(self._handle, '127.0.0.1', 0, subprotocols=[SUBPROTOCOL],
                             max_size=MAX_CLIENT_MESSAGE, compression=None,
                             ping_interval=None)
        self.port = server.sockets[0].getsockname()[1]
        return server

    # --- called from the ROS thread ---------------------------------------------------------

    def _post(self, function: Any, *args: Any) -> None:
        if self.loop is not None and not self.loop.is_closed():
            self.loop.call_soon_threadsafe(function, *args)

    def channels_changed(self, added: list[ChannelInfo], removed: list[int]) -> None:
        self._post(self._broadcast_channels, added, removed)

    def services_changed(self, added: list[ServiceInfo], removed: list[int]) -> None:
        self._post(self._broadcast_services, added, removed)

    def message(self, channel_id: int, stamp_ns: int, data: bytes) -> None:
        # Batched: one loop wake-up for however many messages arrived meanwhile.
        with self._pending_lock:
            self._pending.append((channel_id, stamp_ns, data))
            if self._scheduled:
                return
            self._scheduled = True
        self._post(self._deliver)

    def parameters_changed(self, values: list[dict[str, Any]]) -> None:
        self._post(self._broadcast_parameters, values)

    def graph_changed(self, graph: Graph) -> None:
        self._post(self._broadcast_graph, graph)

    def time(self, stamp_ns: int) -> None:
        self._post(self._broadcast, struct.pack('<BQ', TIME, stamp_ns), True)

    # --- on the loop ------------------------------------------------------------------------

    def _deliver(self) -> None:
        with self._pending_lock:
            batch, self._pending = self._pending, collections.deque()
            self._scheduled = False
        for channel_id, stamp, data in batch:
            for client in self.clients.values():
                subscription = client.by_channel.get(channel_id)
                if subscription is not None:
                    client.send(struct.pack('<BIQ', MESSAGE_DATA, subscription, stamp) + data,
                                droppable=True)

    def _broadcast(self, frame: bytes | str, droppable: bool = False) -> None:
        for client in self.clients.values():
            client.send(frame, droppable)

    def _broadcast_channels(self, added: list[ChannelInfo], removed: list[int]) -> None:
        if removed:
            for client in self.clients.values():
                for channel_id in removed:
                    subscription = client.by_channel.pop(channel_id, None)
                    client.subscriptions.pop(subscription, None)
            self._broadcast(json.dumps({'op': 'unadvertise', 'channelIds': removed}))
        if added:
            self._broadcast(json.dumps({'op': 'advertise',
                                        'channels': [channel_json(c) for c in added]}))

    def _broadcast_services(self, added: list[ServiceInfo], removed: list[int]) -> None:
        if removed:
            self._broadcast(json.dumps({'op': 'unadvertiseServices', 'serviceIds': removed}))
        if added:
            self._broadcast(json.dumps({'op': 'advertiseServices',
                                        'services': [service_json(s) for s in added]}))

    def _broadcast_parameters(self, values: list[dict[str, Any]]) -> None:
        for client in self.clients.values():
            mine = [v for v in values if v['name'] in client.params]
            if mine:
                client.send({'op': 'parameterValues', 'parameters': mine})

    def _broadcast_graph(self, graph: Graph) -> None:
        for client in self.clients.values():
            if client.graph is not None:
                client.send(graph_json(graph, client.graph))
                client.graph = graph

    async def _handle(self, connection: ServerConnection) -> None:
        self._numbers += 1
        client = Client(self, connection, self._numbers)
        self.clients[client.number] = client
        sender = asyncio.create_task(client.sender())
        client.send({'op': 'serverInfo', 'name': 'foxglove_bridge',
                     'capabilities': self.capabilities,
                     'supportedEncodings': list(CLIENT_ENCODINGS),
                     'metadata': {'ROS_DISTRO': 'jazzy'}, 'sessionId': self.session_id})
        channels = list(self.ros.channels.values())
        if channels:
            client.send({'op': 'advertise', 'channels': [channel_json(c) for c in channels]})
        services = list(self.ros.service_infos.values())
        if services and 'services' in self.capabilities:
            client.send({'op': 'advertiseServices',
                         'services': [service_json(s) for s in services]})
        try:
            async for message in connection:
                try:
                    if isinstance(message, str):
                        await self._on_text(client, message)
                    else:
                        await self._on_binary(client, message)
                except (BridgeError, ParameterError) as error:
                    client.status(ERROR, str(error))
        except ConnectionClosed:
            pass
        finally:
            sender.cancel()
            del self.clients[client.number]
            await self._blocking(self._release, client)

    def _release(self, client: Client) -> None:
        for channel_id in list(client.by_channel):
            self.ros.unsubscribe(channel_id, client.key())
        for channel_id in client.advertised:
            self.ros.client_unadvertise(client.key(channel_id))
        self.ros.params.forget(client.key())
        self.ros.watch_graph(client.key(), False)

    def _blocking(self, function: Any, *args: Any) -> Any:
        return asyncio.get_running_loop().run_in_executor(None, function, *args)

    async def _on_text(self, client: Client, text: str) -> None:
        try:
            request = json.loads(text)
        except ValueError as error:
            raise BridgeError(f'Invalid JSON message: {error}') from None
        if not isinstance(request, dict) or not isinstance(request.get('op'), str):
            raise BridgeError("Invalid message: expected a JSON object with a string 'op'")
        handler = getattr(self, '_op_' + request['op'], None)
        if handler is None:
            raise BridgeError(f"Unrecognized client opcode \"{request['op']}\"")
        try:
            await handler(client, request)
        except (KeyError, TypeError, ValueError) as error:
            raise BridgeError(f"Invalid '{request['op']}' message: {error!r}") from None

    def _need(self, capability: str) -> None:
        if capability not in self.capabilities:
            raise BridgeError(f'Server does not support {capability} capability')

    async def _op_subscribe(self, client: Client, request: dict[str, Any]) -> None:
        for item in request['subscriptions']:
            subscription, channel_id = int(item['id']), int(item['channelId'])
            if subscription in client.subscriptions:
                client.status(ERROR, f'Client subscription id {subscription} was already used; '
                              'ignoring subscription')
                continue
            if channel_id not in self.ros.channels:
                client.status(WARNING, f'Channel {channel_id} is not available; '
                              'ignoring subscription')
                continue
            if channel_id in client.by_channel:
                client.status(WARNING, f'Client is already subscribed to channel {channel_id}; '
                              'ignoring subscription')
                continue
            await self._blocking(self.ros.subscribe, channel_id, client.key())
            client.subscriptions[subscription] = channel_id
            client.by_channel[channel_id] = subscription

    async def _op_unsubscribe(self, client: Client, request: dict[str, Any]) -> None:
        for subscription in request['subscriptionIds']:
            channel_id = client.subscriptions.pop(int(subscription), None)
            if channel_id is None:
                client.status(WARNING, f'Client subscription id {subscription} did not exist; '
                              'ignoring unsubscription')
                continue
            client.by_channel.pop(channel_id, None)
            await self._blocking(self.ros.unsubscribe, channel_id, client.key())

    async def _op_advertise(self, client: Client, request: dict[str, Any]) -> None:
        self._need('clientPublish')
        for channel in request['channels']:
            channel_id = int(channel['id'])
            if channel_id in client.advertised:
                client.status(ERROR, f'Channel {channel_id} is already advertised')
                continue
            try:
                await self._blocking(self.ros.client_advertise, client.key(channel_id),
                                     str(channel['topic']), str(channel['encoding']),
                                     str(channel.get('schemaName', '')))
            except BridgeError as error:
                client.status(ERROR, str(error))
                continue
            client.advertised.add(channel_id)

    async def _op_unadvertise(self, client: Client, request: dict[str, Any]) -> None:
        for channel_id in request['channelIds']:
            if int(channel_id) in client.advertised:
                client.advertised.discard(int(channel_id))
                await self._blocking(self.ros.client_unadvertise, client.key(int(channel_id)))

    async def _op_getParameters(self, client: Client, request: dict[str, Any]) -> None:
        self._need('parameters')
        names = [str(n) for n in request['parameterNames']]
        values = await self._blocking(self.ros.params.get, names)
        reply = {'op': 'parameterValues', 'parameters': values}
        if request.get('id') is not None:
            reply['id'] = request['id']
        client.send(reply)

    async def _op_setParameters(self, client: Client, request: dict[str, Any]) -> None:
        self._need('parameters')
        items = [(str(p['name']), p.get('value'), p.get('type')) for p in request['parameters']]
        values = await self._blocking(self.ros.params.set, items)
        if request.get('id') is not None:
            client.send({'op': 'parameterValues', 'parameters': values, 'id': request['id']})

    async def _op_subscribeParameterUpdates(self, client: Client, request: dict[str, Any]
                                            ) -> None:
        self._need('parametersSubscribe')
        names = [str(n) for n in request['parameterNames']]
        client.params.update(names)
        self.ros.params.watch(client.key(), names, True)

    async def _op_unsubscribeParameterUpdates(self, client: Client, request: dict[str, Any]
                                              ) -> None:
        names = [str(n) for n in request['parameterNames']]
        client.params.difference_update(names)
        self.ros.params.watch(client.key(), names, False)

    async def _op_subscribeConnectionGraph(self, client: Client, _request: dict[str, Any]
                                           ) -> None:
        self._need('connectionGraph')
        client.graph = Graph()
        self.ros.watch_graph(client.key(), True)
        current = self.ros.current_graph()
        client.send(graph_json(current, client.graph))
        client.graph = current

    async def _op_unsubscribeConnectionGraph(self, client: Client, _request: dict[str, Any]
                                             ) -> None:
        client.graph = None
        self.ros.watch_graph(client.key(), False)

    async def _op_fetchAsset(self, client: Client, request: dict[str, Any]) -> None:
        self._need('assets')
        request_id, uri = int(request['requestId']), str(request['uri'])
        try:
            data, status, error = await self._blocking(self.ros.fetch_asset, uri), 0, b''
        except BridgeError as failure:
            data, status, error = b'', 1, str(failure).encode()
        client.send(struct.pack('<BIBI', FETCH_ASSET_RESPONSE, request_id, status, len(error))
                    + error + data)

    async def _on_binary(self, client: Client, frame: bytes) -> None:
        if not frame:
            raise BridgeError('Empty binary message')
        opcode = frame[0]
        if opcode == CLIENT_MESSAGE_DATA:
            if len(frame) < 5:
                raise BridgeError('Invalid message data: shorter than its 5-byte header')
            (channel_id,) = struct.unpack_from('<I', frame, 1)
            if channel_id not in client.advertised:
                raise BridgeError(f'Channel {channel_id} is not advertised by this client')
            self.ros.client_publish(client.key(channel_id), frame[5:])
        elif opcode == CLIENT_SERVICE_CALL_REQUEST:
            self._need('services')
            if len(frame) < 13:
                raise BridgeError('Invalid service call request: shorter than its header')
            service_id, call_id, length = struct.unpack_from('<III', frame, 1)
            encoding = frame[13:13 + length].decode(errors='replace')
            payload = frame[13 + length:]
            task = asyncio.create_task(self._call(client, service_id, call_id, encoding, payload))
            client.calls.add(task)  # kept until done: the loop holds tasks only weakly
            task.add_done_callback(client.calls.discard)
        else:
            raise BridgeError(f'Unrecognized client opcode: {opcode}')

    async def _call(self, client: Client, service_id: int, call_id: int, encoding: str,
                    payload: bytes) -> None:
        started = time.monotonic()
        try:
            response = await self._blocking(self.ros.call_service, service_id, encoding, payload)
        except BridgeError as error:
            client.send({'op': 'serviceCallFailure', 'serviceId': service_id, 'callId': call_id,
                         'message': str(error)})
            return
        self.ros.get_logger().debug(f'service call took {time.monotonic() - started:.3f} s')
        client.send(struct.pack('<BIII', SERVICE_CALL_RESPONSE, service_id, call_id, 3) + b'cdr'
                    + response)
