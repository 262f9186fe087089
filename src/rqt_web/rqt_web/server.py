"""The rqt web server (aiohttp): pages, a JSON API and one WebSocket per page for live data.

Started detached by the launchers (rqt_web/launcher.py); `python -m rqt_web.server --help`.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import sys
import threading
import time
from pathlib import Path
from typing import Any

from aiohttp import WSMsgType, web
from node_runtime.discovery import announce_often
from node_runtime.spinning import SIGNAL_CHECK_PERIOD, stop_on_signals

from rqt_web import forms, instance, rviz, security, tf_feed
from rqt_web.ros_bridge import RosBridge

STATIC = Path(__file__).resolve().parent / 'static'
# The browser libraries scripts/setup installed with `npm ci` (package.json of rqt_web).
VENDOR_FILES = {
    'cytoscape.min.js': 'cytoscape/dist/cytoscape.min.js',
    'cytoscape-dagre.js': 'cytoscape-dagre/dist/cytoscape-dagre.js',
    'cytoscape-svg.js': 'cytoscape-svg/cytoscape-svg.js',
    # three.js for the RViz page: the ES modules, loaded through an import map
    'three.module.js': 'three/build/three.module.js',
    'three.core.js': 'three/build/three.core.js',
    'OrbitControls.js': 'three/examples/jsm/controls/OrbitControls.js',
    'STLLoader.js': 'three/examples/jsm/loaders/STLLoader.js',
    # Mesh loaders under their examples/jsm layout, so their relative imports resolve.
    'addons/loaders/ColladaLoader.js': 'three/examples/jsm/loaders/ColladaLoader.js',
    'addons/loaders/TGALoader.js': 'three/examples/jsm/loaders/TGALoader.js',
    'addons/loaders/collada/ColladaParser.js':
        'three/examples/jsm/loaders/collada/ColladaParser.js',
    'addons/loaders/collada/ColladaComposer.js':
        'three/examples/jsm/loaders/collada/ColladaComposer.js',
    'addons/loaders/OBJLoader.js': 'three/examples/jsm/loaders/OBJLoader.js',
}
SERVICE_TIMEOUT_MAX = 60.0
MONITOR_WINDOW = 5.0  # seconds of messages the Topics page's Hz and bandwidth average over
LATEST_YAML_LIMIT = 8000  # characters of a message shown in the Topics page
SEND_QUEUE = 2000  # JSON messages waiting for a slow page; beyond that they are dropped
TWIST_KEYS = {'ArrowUp': (2.0, 0.0), 'ArrowDown': (-2.0, 0.0),
              'ArrowLeft': (0.0, 2.0), 'ArrowRight': (0.0, -2.0)}


def vendor_dir() -> Path:
    return Path(os.environ.get('RQT_WEB_JS_DIR', Path(sys.prefix) / 'rqt_web_js')) / 'node_modules'


# --------------------------------------------------------------------------------------
# Pages and API
# --------------------------------------------------------------------------------------

async def page(request: web.Request) -> web.Response:
    name = request.match_info.get('page') or 'index'
    if name not in instance.PAGES:
        raise web.HTTPNotFound(text=f'no page {name!r}')
    shell = (STATIC / 'page.html').read_text()
    html = shell.replace('{{PAGE}}', name).replace('{{TITLE}}', instance.PAGES[name][1])
    return web.Response(text=html, content_type='text/html',
                        headers={'Cache-Control': 'no-store'})


async def static_file(request: web.Request) -> web.FileResponse:
    name = request.match_info['name']
    path = STATIC / name
    # Folders too (the RViz page's ES modules are static/rviz/...), nothing outside STATIC.
    # .js goes out as text/javascript (mimetypes), which module scripts require.
    if name.startswith('/') or '..' in name.split('/') or not path.is_file():
        raise web.HTTPNotFound()
    return web.FileResponse(path)


async def vendor_file(request: web.Request) -> web.FileResponse:
    relative = VENDOR_FILES.get(request.match_info['name'])
    path = vendor_dir() / relative if relative else None
    if path is None or not path.is_file():
        raise web.HTTPNotFound(text='browser library not installed: run scripts/setup '
                               '(it needs npm)')
    return web.FileResponse(path)


async def ping(request: web.Request) -> web.Response:
    return web.json_response({'ok': True, 'pid': os.getpid(),
                              'vendor': all((vendor_dir() / p).is_file()
                                            for p in VENDOR_FILES.values())})


async def graph(request: web.Request) -> web.Response:
    bridge: RosBridge = request.app['bridge']
    return web.json_response(await bridge.run(bridge.snapshot))


async def interface(request: web.Request) -> web.Response:
    name = request.query.get('type', '')
    kind = request.query.get('kind', 'msg')
    part = request.query.get('part', '')
    try:
        cls = forms.interface_class(name, kind)
        if kind == 'srv':
            cls = cls.Request if part != 'response' else cls.Response
        elif kind == 'action':
            cls = {'result': cls.Result, 'feedback': cls.Feedback}.get(part, cls.Goal)
        return web.json_response({'fields': forms.describe(cls)})
    except forms.FormError as error:
        return web.json_response({'error': str(error)})


async def _json_body(request: web.Request) -> dict:
    try:
        body = await request.json()
    except (ValueError, UnicodeDecodeError):
        raise forms.FormError('the request body is not JSON') from None
    if not isinstance(body, dict):
        raise forms.FormError('the request body must be a JSON object')
    return body


def _error(message: str) -> web.Response:
    return web.json_response({'error': message})


async def call_service(request: web.Request) -> web.Response:
    bridge: RosBridge = request.app['bridge']
    from rosidl_runtime_py import message_to_ordereddict
    try:
        body = await _json_body(request)
        name, srv_type = str(body.get('name', '')), str(body.get('type', ''))
        timeout = body.get('timeout', 5.0)
        if isinstance(timeout, bool) or not isinstance(timeout, (int, float)) \
                or not 0 < timeout <= SERVICE_TIMEOUT_MAX:
            raise forms.FormError(f'timeout must be a number of seconds in (0, '
                                  f'{SERVICE_TIMEOUT_MAX:g}], got {timeout!r}')
        srv_class = forms.interface_class(srv_type, 'srv')
        msg = forms.build(srv_class.Request, body.get('values'))
        started = time.monotonic()
        response = await bridge.call_service(name, srv_type, msg, float(timeout))
    except (forms.FormError, TimeoutError) as error:
        return _error(str(error))
    except Exception as error:  # e.g. rclpy refusing the service name
        return _error(f'call failed: {error}')
    return web.json_response({'response': message_to_ordereddict(response),
                              'seconds': round(time.monotonic() - started, 4)})


async def publish(request: web.Request) -> web.Response:
    bridge: RosBridge = request.app['bridge']
    try:
        body = await _json_body(request)
        topic, msg_type = str(body.get('topic', '')), str(body.get('type', ''))
        msg = forms.build(forms.interface_class(msg_type, 'msg'), body.get('values'))
        _check_topic_name(topic)
        await bridge.publish(topic, msg_type, msg)
    except forms.FormError as error:
        return _error(str(error))
    return web.json_response({'published': True})


def _check_topic_name(name: str) -> None:
    problem = forms.topic_name_problem(name)
    if problem is not None:
        raise forms.FormError(f'invalid topic name {name!r}: {problem}')


def _check_node_name(name: str) -> None:
    """A fully qualified node name is a valid absolute name: its services are named under it."""
    from rclpy.validate_full_topic_name import validate_full_topic_name
    try:
        validate_full_topic_name(name, is_service=True)
    except Exception as error:  # rclpy's InvalidServiceNameException and friends
        raise forms.FormError(f'invalid node name {name!r}: {error}') from None


async def _parameter_infos(bridge: RosBridge, node: str, names: list[str] | None = None
                           ) -> list[dict]:
    from rcl_interfaces.srv import DescribeParameters, GetParameters, ListParameters

    _check_node_name(node)
    if names is None:
        listed = await bridge.call_service(f'{node}/list_parameters',
                                           'rcl_interfaces/srv/ListParameters',
                                           ListParameters.Request(), 5.0)
        names = sorted(listed.result.names)
    described = await bridge.call_service(f'{node}/describe_parameters',
                                          'rcl_interfaces/srv/DescribeParameters',
                                          DescribeParameters.Request(names=names), 5.0)
    values = await bridge.call_service(f'{node}/get_parameters',
                                       'rcl_interfaces/srv/GetParameters',
                                       GetParameters.Request(names=names), 5.0)
    return [forms.describe_parameter(d, v)
            for d, v in zip(described.descriptors, values.values, strict=False)]


async def parameters(request: web.Request) -> web.Response:
    node = request.query.get('node', '')
    try:
        infos = await _parameter_infos(request.app['bridge'], node)
    except forms.FormError as error:
        return _error(str(error))
    except TimeoutError as error:
        return _error(f'{node} offers no parameter services ({error})')
    return web.json_response({'node': node, 'parameters': infos})


async def set_parameter(request: web.Request) -> web.Response:
    from rcl_interfaces.msg import Parameter
    from rcl_interfaces.srv import SetParameters
    bridge: RosBridge = request.app['bridge']
    try:
        body = await _json_body(request)
        node, name = str(body.get('node', '')), str(body.get('name', ''))
        infos = await _parameter_infos(bridge, node, [name])
        if not infos or infos[0]['type'] == 'not set':
            raise forms.FormError(f"{node} has no parameter '{name}'")
        value = forms.parameter_value(infos[0], body.get('value'))
        answer = await bridge.call_service(
            f'{node}/set_parameters', 'rcl_interfaces/srv/SetParameters',
            SetParameters.Request(parameters=[Parameter(name=name, value=value)]), 5.0)
    except (forms.FormError, TimeoutError) as error:
        return _error(str(error))
    result = answer.results[0]
    if not result.successful:
        return _error(f'Setting parameter failed: {result.reason}')
    return web.json_response({'set': True})


# --------------------------------------------------------------------------------------
# WebSocket: live streams for one page
# --------------------------------------------------------------------------------------

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
                                    qos=_canvas_qos())

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
        _check_topic_name(topic)
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


def _canvas_qos() -> Any:
    from rqt_web.ros_bridge import CANVAS_QOS
    return CANVAS_QOS


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


async def _monitor_loop(app: web.Application) -> None:
    while True:
        await asyncio.sleep(1.0)
        for session in list(app['sessions']):
            if session.monitors:
                session.monitor_report()


# --------------------------------------------------------------------------------------
# Application
# --------------------------------------------------------------------------------------

def make_app(token: str, bind_host: str, port_holder: dict) -> web.Application:
    app = web.Application(middlewares=[security.middleware(token, bind_host, port_holder)],
                          client_max_size=1 << 20)
    app['graph_sessions'] = set()
    app['log_sessions'] = set()
    app['sessions'] = set()

    app.router.add_routes([
        web.get('/', page), web.get('/api/ping', ping), web.get('/api/graph', graph),
        web.get('/api/interface', interface), web.post('/api/service/call', call_service),
        web.post('/api/topic/publish', publish), web.get('/api/parameters', parameters),
        web.post('/api/parameters/set', set_parameter), web.get('/ws', websocket),
        web.get('/static/{name:.+}', static_file), web.get('/vendor/{name:.+}', vendor_file),
        web.get('/{page}', page)])
    tf_feed.add_routes(app)  # /api/tf/...: the TF Tree and RViz pages' data
    rviz.add_routes(app)  # /api/rviz/...: .rviz files, robot description, meshes

    async def start_ros(app: web.Application) -> None:
        bridge = RosBridge(asyncio.get_running_loop())
        app['bridge'] = bridge

        def graph_changed(snapshot: dict) -> None:
            for session in list(app['graph_sessions']):
                session.send({'op': 'graph', 'graph': snapshot})

        def logged(entry: dict) -> None:
            for session in list(app['log_sessions']):
                session.send({'op': 'log', 'entries': [entry]})
        bridge.on_graph = graph_changed
        bridge.on_log = logged
        app['monitor'] = asyncio.ensure_future(_monitor_loop(app))

    async def stop_ros(app: web.Application) -> None:
        app['monitor'].cancel()
        app['bridge'].shutdown()

    app.on_startup.append(start_ros)
    app.on_cleanup.append(stop_ros)
    return app


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog='python -m rqt_web.server', description=__doc__)
    parser.add_argument('--host', default='127.0.0.1')
    parser.add_argument('--port', type=int, default=0)
    parser.add_argument('--state-file', default=None,
                        help='where to write pid, port and token (default: per ROS settings)')
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if args.host not in ('127.0.0.1', 'localhost', '::1'):
        print(f'WARNING: listening on {args.host}: other machines can reach this server; '
              'only the token protects it', file=sys.stderr, flush=True)
    # node_runtime's handlers (not asyncio's): Ctrl-C and SIGTERM set `stop` and give the
    # server its shutdown budget; a SIGTERM while it stops ends it at once.
    stop = threading.Event()
    stop_on_signals(stop)
    announce_often()  # without it, 1 node start in 6 reached the graph only after 2-3 s
    token = security.new_token()
    port_holder = {'port': args.port}
    app = make_app(token, args.host, port_holder)
    state_path = Path(args.state_file) if args.state_file else instance.state_file()
    asyncio.run(_serve(app, args.host, port_holder, token, state_path, stop))
    return 0


async def _serve(app: web.Application, host: str, port_holder: dict, token: str,
                 state_path: Path, stop: threading.Event) -> None:
    runner = web.AppRunner(app, handle_signals=False, access_log=None)
    await runner.setup()
    site = web.TCPSite(runner, host, port_holder['port'])
    await site.start()
    port_holder['port'] = runner.addresses[0][1]
    server = instance.Instance(os.getpid(), host, port_holder['port'], token)
    instance.write_state(state_path, server)
    print(f'rqt web app listening on {host}:{server.port} (pid {server.pid})', flush=True)
    try:
        # Polled: the handler runs on this thread, between two of the loop's bytecodes.
        while not stop.is_set():
            await asyncio.sleep(SIGNAL_CHECK_PERIOD)
    finally:
        if instance.read_state(state_path) == server:
            state_path.unlink(missing_ok=True)
        await runner.cleanup()


if __name__ == '__main__':
    sys.exit(main())
