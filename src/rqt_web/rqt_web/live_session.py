"""The live half of a page: its WebSocket (GET /ws) and what it watches.

A page sends JSON objects `{"op": ...}`; each op is a `Session.op_*` method: `graph` and
`console` (pushed as the graph changes and as /rosout logs), `canvas`/`uncanvas` (turtlesim's
frames, binary), `teleop`, `monitor`/`unmonitor` (the Topics page's Hz, bandwidth and latest
message, reported once a second by `monitor_loop`), `goal` and `cancel` (the Actions page:
feedback, then the result). A bad op is answered `{"op": "error", "error": "..."}`.
"""

from __future__ import annotations

import asyncio
import json
import sys
import time
from typing import Any

from aiohttp import WSMsgType, web

from rqt_web import forms
from rqt_web.ros_bridge import CANVAS_QOS, RosBridge

MONITOR_WINDOW = 5.0  # seconds of messages the Topics page's Hz and bandwidth average over
LATEST_YAML_LIMIT = 8000  # characters of a message shown in the Topics page
SEND_QUEUE = 2000  # JSON messages waiting for a slow page; beyond that they are dropped
TWIST_KEYS = {'ArrowUp': (2.0, 0.0), 'ArrowDown': (-2.0, 0.0),
              'ArrowLeft': (0.0, 2.0), 'ArrowRight': (0.0, -2.0)}


class Session:
    """One page's WebSocket: what it watches, and a writer that never lets it pile up.

    JSON messages wait in a bounded queue; canvas frames are kept one per canvas (the newest
    replaces an unsent older one), so a slow page gets fewer frames, never a backlog.
    """

    def __init__(self, app: web.Application, ws: web.WebSocketResponse) -> None:
        self.app = app
        self.bridge: RosBridge = app['bridge']
        self.ws = ws
        self.queue: asyncio.Queue = asyncio.Queue(maxsize=SEND_QUEUE)
        self.frames: dict[str, bytes] = {}
        self.watching_graph = False
        self.watching_log = False
        self.canvases: dict[str, Any] = {}
        self.monitors: dict[tuple[str, str], dict] = {}
        self.goals: dict[str, Any] = {}
        self.tasks: set[asyncio.Task] = set()

    def send(self, message: dict) -> None:
        try:
            self.queue.put_nowait(json.dumps(message))
        except asyncio.QueueFull:
            pass

    def send_frame(self, topic: str, data: bytes) -> None:
        if topic not in self.frames:
            try:
                self.queue.put_nowait(('frame', topic))
            except asyncio.QueueFull:
                return
        self.frames[topic] = data

    async def writer(self) -> None:
        try:
            while not self.ws.closed:
                item = await self.queue.get()
                if isinstance(item, tuple):
                    data = self.frames.pop(item[1], None)
                    if data is not None:
                        await self.ws.send_bytes(data)
                else:
                    await self.ws.send_str(item)
        except (ConnectionError, RuntimeError):
            pass  # the page went away: the reader side ends the session

    def spawn(self, coroutine: Any) -> None:
        task = asyncio.ensure_future(coroutine)
        self.tasks.add(task)
        task.add_done_callback(self.tasks.discard)

    async def handle(self, message: dict) -> None:
        op = message.get('op')
        handler = getattr(self, f'op_{op}', None) if isinstance(op, str) else None
        if handler is None:
            self.send({'op': 'error', 'error': f'unknown op {op!r}'})
            return
        try:
            await handler(message)
        except (forms.FormError, TimeoutError) as error:
            self.send({'op': 'error', 'id': message.get('id'), 'error': str(error)})
        except Exception as error:  # a ROS-side failure: one line in the page, logged here
            print(f'rqt: {op} failed: {error!r}', file=sys.stderr, flush=True)
            self.send({'op': 'error', 'id': message.get('id'), 'error': f'{op} failed: {error}'})

    # -- graph and console
    async def op_graph(self, message: dict) -> None:
        if not self.watching_graph:
            self.watching_graph = True
            self.app['graph_sessions'].add(self)
            self.bridge.graph_listeners += 1
        self.send({'op': 'graph', 'graph': await self.bridge.run(self.bridge.snapshot)})

    async def op_console(self, message: dict) -> None:
        self.watching_log = True
        self.app['log_sessions'].add(self)
        self.send({'op': 'log', 'entries': list(self.bridge.log)})

    # -- turtlesim canvases and teleop
    async def op_canvas(self, message: dict) -> None:
        topic = str(message.get('topic', ''))
        if not topic.endswith('/_canvas') or topic in self.canvases:
            return

        def received(msg: Any) -> None:
            label = msg.layout.dim[0].label if msg.layout.dim else ''
            header = json.dumps({'topic': topic, 'label': label, 'recv': time.time()})
            self.send_frame(topic, header.encode() + b'\n' + msg.data.tobytes())
        self.canvases[topic] = received
        await self.bridge.subscribe(topic, 'std_msgs/msg/UInt8MultiArray', received,
                                    qos=CANVAS_QOS)

    async def op_uncanvas(self, message: dict) -> None:
        topic = str(message.get('topic', ''))
        callback = self.canvases.pop(topic, None)
        if callback is not None:
            await self.bridge.unsubscribe(topic, 'std_msgs/msg/UInt8MultiArray', callback)

    async def op_teleop(self, message: dict) -> None:
        from geometry_msgs.msg import Twist
        topic = str(message.get('topic', ''))
        if not topic.endswith('/cmd_vel') or message.get('key') not in TWIST_KEYS:
            raise forms.FormError('teleop needs a .../cmd_vel topic and an arrow key')
        forms.check_topic_name(topic)
        twist = Twist()
        twist.linear.x, twist.angular.z = TWIST_KEYS[message['key']]
        await self.bridge.publish(topic, 'geometry_msgs/msg/Twist', twist)

    # -- topics
    async def op_monitor(self, message: dict) -> None:
        topic, msg_type = str(message.get('topic', '')), str(message.get('type', ''))
        key = (topic, msg_type)
        if key in self.monitors:
            return
        forms.interface_class(msg_type, 'msg')
        stats: dict = {'arrivals': [], 'latest': None}

        def received(raw: bytes) -> None:
            now = time.monotonic()
            arrivals = stats['arrivals']
            arrivals.append((now, len(raw)))
            while arrivals and arrivals[0][0] < now - MONITOR_WINDOW:
                arrivals.pop(0)
            del arrivals[:-10000]  # bounded even for a topic at tens of kHz
            stats['latest'] = raw
        stats['callback'] = received
        self.monitors[key] = stats
        await self.bridge.subscribe(topic, msg_type, received, raw=True)

    async def op_unmonitor(self, message: dict) -> None:
        key = (str(message.get('topic', '')), str(message.get('type', '')))
        stats = self.monitors.pop(key, None)
        if stats is not None:
            await self.bridge.unsubscribe(*key, stats['callback'])

    def monitor_report(self) -> None:
        from rclpy.serialization import deserialize_message

        from rosidl_runtime_py import message_to_yaml
        now = time.monotonic()
        for (topic, msg_type), stats in self.monitors.items():
            arrivals = [a for a in stats['arrivals'] if a[0] >= now - MONITOR_WINDOW]
            hz = bw = None
            if len(arrivals) >= 2:
                span = arrivals[-1][0] - arrivals[0][0]
                if span > 0:
                    hz = (len(arrivals) - 1) / span
                    bw = sum(size for _, size in arrivals[1:]) / span
            latest = None
            if stats['latest'] is not None:
                cls = forms.interface_class(msg_type, 'msg')
                latest = message_to_yaml(deserialize_message(stats['latest'], cls))
                latest = latest[:LATEST_YAML_LIMIT]
            self.send({'op': 'monitor', 'topic': topic, 'type': msg_type, 'hz': hz, 'bw': bw,
                       'latest': latest})

    # -- actions
    async def op_goal(self, message: dict) -> None:
        from rosidl_runtime_py import message_to_ordereddict
        goal_id = str(message.get('id', ''))
        name, action_type = str(message.get('action', '')), str(message.get('type', ''))
        action_class = forms.interface_class(action_type, 'action')
        goal = forms.build(action_class.Goal, message.get('values'))
        client = await self.bridge.action_client(name, action_type)
        deadline = time.monotonic() + 5.0
        while not client.server_is_ready():
            if time.monotonic() > deadline:
                raise TimeoutError(f'action server {name} is not available')
            await asyncio.sleep(0.02)

        def feedback(msg: Any) -> None:
            self.bridge.loop.call_soon_threadsafe(self.send, {
                'op': 'feedback', 'id': goal_id, 'feedback': message_to_ordereddict(msg.feedback)})
        sent = await self.bridge.run(lambda: client.send_goal_async(goal, feedback))
        handle = await self.bridge.to_asyncio(sent)
        if not handle.accepted:
            self.send({'op': 'goal_rejected', 'id': goal_id})
            return
        self.goals[goal_id] = handle
        self.send({'op': 'goal_accepted', 'id': goal_id})
        self.spawn(self._await_result(goal_id, handle))

    async def _await_result(self, goal_id: str, handle: Any) -> None:
        from action_msgs.msg import GoalStatus

        from rosidl_runtime_py import message_to_ordereddict
        pending = await self.bridge.run(handle.get_result_async)
        result = await self.bridge.to_asyncio(pending)
        self.goals.pop(goal_id, None)
        status = {GoalStatus.STATUS_SUCCEEDED: 'SUCCEEDED', GoalStatus.STATUS_CANCELED:
                  'CANCELED', GoalStatus.STATUS_ABORTED: 'ABORTED'}.get(result.status,
                                                                        str(result.status))
        self.send({'op': 'goal_result', 'id': goal_id, 'status': status,
                   'result': message_to_ordereddict(result.result)})

    async def op_cancel(self, message: dict) -> None:
        handles = ([self.goals[message['id']]] if message.get('id') in self.goals
                   else list(self.goals.values()) if message.get('id') is None else [])
        for handle in handles:
            await self.bridge.run(handle.cancel_goal_async)

    async def close(self) -> None:
        self.app['graph_sessions'].discard(self)
        self.app['log_sessions'].discard(self)
        if self.watching_graph:
            self.bridge.graph_listeners -= 1
        for topic in list(self.canvases):
            await self.op_uncanvas({'topic': topic})
        for topic, msg_type in list(self.monitors):
            await self.op_unmonitor({'topic': topic, 'type': msg_type})
        for task in list(self.tasks):
            task.cancel()


async def websocket(request: web.Request) -> web.WebSocketResponse:
    ws = web.WebSocketResponse(heartbeat=20.0, max_msg_size=1 << 20)
    await ws.prepare(request)
    session = Session(request.app, ws)
    request.app['sessions'].add(session)
    writer = asyncio.ensure_future(session.writer())
    try:
        async for frame in ws:
            if frame.type != WSMsgType.TEXT:
                continue
            try:
                message = json.loads(frame.data)
            except ValueError:
                session.send({'op': 'error', 'error': 'messages must be JSON'})
                continue
            if isinstance(message, dict):
                session.spawn(session.handle(message))
            else:
                session.send({'op': 'error', 'error': 'messages must be JSON objects'})
    finally:
        writer.cancel()
        request.app['sessions'].discard(session)
        await session.close()
    return ws


async def monitor_loop(app: web.Application) -> None:
    """Every second, each session's Topics page gets its monitors' figures."""
    while True:
        await asyncio.sleep(1.0)
        for session in list(app['sessions']):
            if session.monitors:
                session.monitor_report()
