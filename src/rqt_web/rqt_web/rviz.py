"""Server side of the RViz page: .rviz files, the robot description, mesh files.

TF comes from `tf_feed` (one tf2_ros Buffer for the whole app). Here:

- GET /api/rviz/config?path=FILE.rviz: the file's Global Options (Fixed Frame, Background
  Color) and its Displays (class, name, enabled, topic) as JSON, read from upstream rviz2's
  YAML layout; `path` must name an existing .rviz file.
- GET /api/rviz/description?topic=/robot_description: the latest std_msgs/String on that
  topic (transient local, as robot_state_publisher latches it) and a counter that grows with
  each new one, so the page reloads the model only when it changed.
- GET /api/rviz/markers?topic=/visualization_marker[&type=Marker|MarkerArray]: the markers
  alive now (ADD/MODIFY replace by namespace and id, DELETE and DELETEALL remove, lifetime
  expires), each as JSON with its frame, pose, scale, colour, points and text.
- GET /api/rviz/latest?topic=T&type=pkg/msg/Type: the latest message on T as JSON (Pose,
  PoseArray, Path, Odometry and LaserScan displays), null before the first.
- GET /api/rviz/resource?uri=package://PKG/PATH or file:///PATH: a mesh or texture file
  (.stl .dae .obj .mtl .png .jpg), package:// resolved through the ament index.
- GET /api/rviz/cloud?topic=T&after=N, /api/rviz/image?topic=T&after=N and
  /api/rviz/map?topic=T&after=N (PointCloud2, Image and Map displays, a map transient
  local; &reliability=Best Effort as the display's Topic QoS, else reliable): the latest
  message newer than the page's N, waited for up to 1 s (204 No Content if none came), as
  binary made once per message with numpy: a cloud's finite points as float32 x, y, z then,
  if coloured, uint8 r, g, b per point; an image or a map as RGBA bytes. The `X-Rviz`
  header gives JSON: seq, frame, points or width/height (a map: resolution, origin), colour.
- POST /api/rviz/tool {tool: initialpose|goal|point, topic, frame, x, y, z, yaw}: what the
  tool belt's 2D Pose Estimate, 2D Goal Pose and Publish Point publish, stamped now.
"""

from __future__ import annotations

import asyncio
import json
import math
import os
import time
from pathlib import Path
from typing import Any

import yaml
from aiohttp import web

RESOURCE_SUFFIXES = ('.stl', '.dae', '.obj', '.mtl', '.png', '.jpg', '.jpeg')
MAX_TOPIC = 256


def _absolute_topic(topic: str) -> bool:
    """A topic name a subscription or publisher can have (rclpy would raise on any other)."""
    from rqt_web.forms import topic_name_problem
    return len(topic) <= MAX_TOPIC and topic_name_problem(topic) is None


def read_rviz(path: str) -> dict:
    """The parts of an upstream .rviz file the page shows; ValueError naming what is wrong."""
    if not path.endswith('.rviz'):
        raise ValueError(f'path must name a .rviz file, got {path!r}')
    try:
        with open(path, encoding='utf-8') as f:
            data = yaml.safe_load(f)
    except OSError as error:
        raise ValueError(f'cannot read {path}: {error.strerror}') from None
    except yaml.YAMLError as error:
        raise ValueError(f'{path} is not YAML: {" ".join(str(error).split())}') from None
    manager = (data or {}).get('Visualization Manager') if isinstance(data, dict) else None
    if not isinstance(manager, dict):
        raise ValueError(f"{path}: no 'Visualization Manager' section")
    options = manager.get('Global Options') or {}
    background = str(options.get('Background Color', '48; 48; 48'))
    try:
        rgb = [int(v) for v in background.split(';')][:3]
    except ValueError:
        rgb = [48, 48, 48]
    views = ((manager.get('Views') or {}).get('Current') or {})
    tools = [{'class': str(t.get('Class', '')), 'topic': _topic(t)}
             for t in manager.get('Tools') or [] if isinstance(t, dict)]
    return {'tools': tools, 'path': path, 'fixed_frame': str(options.get('Fixed Frame', 'map')),
            'background': rgb, 'displays': [_display(d) for d in manager.get('Displays') or []
                                            if isinstance(d, dict)],
            'view': {k: views.get(k) for k in ('Class', 'Distance', 'Pitch', 'Yaw', 'Scale',
                                                 'X', 'Y')}}


def _topic(d: dict) -> Any:
    topic = d.get('Topic')
    return topic.get('Value') if isinstance(topic, dict) else topic


def _display(d: dict) -> dict:
    topic = _topic(d)
    qos = d.get('Topic') if isinstance(d.get('Topic'), dict) else {}
    description = d.get('Description Topic')
    if isinstance(description, dict):
        topic = description.get('Value', topic)
    return {'class': str(d.get('Class', '')), 'name': str(d.get('Name', '')),
            'enabled': bool(d.get('Value', True)), 'topic': topic,
            'alpha': d.get('Alpha', 1),
            'reliability': str(qos.get('Reliability Policy', 'Reliable')),
            'settings': {k: v for k, v in d.items() if isinstance(v, (str, int, float, bool))}}


class DescriptionFeed:
    """Latest robot description per topic; subscriptions made on the ROS thread."""

    def __init__(self, bridge: Any) -> None:
        self.bridge = bridge
        self.latest: dict[str, tuple[int, str]] = {}

    def subscribe(self, topic: str) -> None:
        if topic in self.latest:
            return
        from rclpy.qos import DurabilityPolicy, QoSProfile
        from std_msgs.msg import String
        self.latest[topic] = (0, '')

        def received(msg: String) -> None:
            self.latest[topic] = (self.latest[topic][0] + 1, msg.data)
        self.bridge.node.create_subscription(
            String, topic, received,
            QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))


class MarkerFeed:
    """Markers alive per topic; subscriptions made on the ROS thread."""

    def __init__(self, bridge: Any) -> None:
        self.bridge = bridge
        self.markers: dict[str, dict[tuple[str, int], dict]] = {}
        self.version = 0  # grows with every marker received: the page re-places it then

    def subscribe(self, topic: str, kind: str) -> None:
        if topic in self.markers:
            return
        from visualization_msgs.msg import Marker, MarkerArray
        self.markers[topic] = {}
        if kind == 'MarkerArray':
            self.bridge.node.create_subscription(
                MarkerArray, topic, lambda msg: [self.apply(topic, m) for m in msg.markers], 10)
        else:
            self.bridge.node.create_subscription(Marker, topic,
                                                 lambda m: self.apply(topic, m), 10)

    def apply(self, topic: str, m: Any) -> None:
        alive = self.markers[topic]
        self.version += 1
        if m.action == 3:  # DELETEALL
            alive.clear()
        elif m.action == 2:  # DELETE
            alive.pop((m.ns, m.id), None)
        else:
            lifetime = m.lifetime.sec + m.lifetime.nanosec * 1e-9
            p, q = m.pose.position, m.pose.orientation
            alive[(m.ns, m.id)] = {
                'ns': m.ns, 'id': m.id, 'type': m.type, 'frame': m.header.frame_id,
                'position': [p.x, p.y, p.z], 'orientation': [q.x, q.y, q.z, q.w],
                'scale': [m.scale.x, m.scale.y, m.scale.z],
                'color': [m.color.r, m.color.g, m.color.b, m.color.a],
                'points': [[v.x, v.y, v.z] for v in m.points],
                'colors': [[c.r, c.g, c.b, c.a] for c in m.colors], 'text': m.text,
                'mesh': m.mesh_resource, 'embedded': m.mesh_use_embedded_materials,
                'frame_locked': m.frame_locked, 'version': self.version,
                'expires': time.monotonic() + lifetime if lifetime > 0 else None}

    def alive(self, topic: str) -> list[dict]:
        now = time.monotonic()
        markers = self.markers[topic]
        for key in [k for k, m in markers.items() if m['expires'] and m['expires'] < now]:
            del markers[key]
        return [{k: v for k, v in m.items() if k != 'expires'} for m in markers.values()]


async def markers_route(request: web.Request) -> web.Response:
    topic = request.query.get('topic', '/visualization_marker')
    kind = request.query.get('type', 'Marker')
    if not _absolute_topic(topic) or kind not in ('Marker', 'MarkerArray'):
        raise web.HTTPBadRequest(text='topic must be an absolute topic name and type Marker '
                                 f'or MarkerArray, got {topic!r}, {kind!r}\n')
    app = request.app
    if 'rviz_markers' not in app:
        app['rviz_markers'] = MarkerFeed(app['bridge'])
    feed = app['rviz_markers']
    markers = await app['bridge'].run(lambda: (feed.subscribe(topic, kind), feed.alive(topic)))
    return web.json_response({'topic': topic, 'markers': markers[1]})


LATEST_TYPES = ('geometry_msgs/msg/PoseStamped', 'geometry_msgs/msg/PoseArray',
                'nav_msgs/msg/Path', 'nav_msgs/msg/Odometry', 'sensor_msgs/msg/LaserScan')


async def latest_route(request: web.Request) -> web.Response:
    topic, kind = request.query.get('topic', ''), request.query.get('type', '')
    if not _absolute_topic(topic) or kind not in LATEST_TYPES:
        raise web.HTTPBadRequest(text=f'topic must be an absolute topic name and type one of '
                                 f'{", ".join(LATEST_TYPES)}, got {topic!r}, {kind!r}\n')
    app = request.app
    latest = app.setdefault('rviz_latest', {})
    if (topic, kind) not in latest:
        latest[(topic, kind)] = None

        def received(msg: Any) -> None:
            latest[(topic, kind)] = msg
        await app['bridge'].subscribe(topic, kind, received)
    from rqt_web.forms import message_to_ordered_value
    msg = latest[(topic, kind)]
    return web.json_response({'topic': topic, 'msg': None if msg is None
                              else message_to_ordered_value(msg)})


# ------------------------------------------------------------------ PointCloud2 and Image
# PointField datatypes (sensor_msgs/msg/PointField) as numpy type codes.
POINT_FIELD_TYPES = {1: 'i1', 2: 'u1', 3: 'i2', 4: 'u2', 5: 'i4', 6: 'u4', 7: 'f4', 8: 'f8'}
STREAM_WAIT = 1.0  # seconds a page's request waits for a newer message


def _rainbow(value: Any) -> Any:
    """rviz's getRainbowColor (HSV hue 0 to 0.83) of values in [0, 1]: uint8 (n, 3)."""
    import numpy as np
    h = np.clip(value, 0.0, 1.0) * 5.0 + 1.0
    i = np.floor(h)
    f = h - i
    f = np.where(i % 2 == 0, 1.0 - f, f)
    n = 1.0 - f
    zero, one = np.zeros_like(h), np.ones_like(h)
    r = np.select([i <= 1, i == 2, i == 3, i == 4], [n, zero, zero, n], one)
    g = np.select([i <= 1, i == 2, i == 3, i == 4], [zero, n, one, one], n)
    b = np.select([i <= 1, i == 2, i == 3, i == 4], [one, one, n, zero], zero)
    return (np.stack([r, g, b], axis=1) * 255.0 + 0.5).astype(np.uint8)


def _packed(msg: Any) -> Any:
    """The message's points as a numpy byte array of width * height * point_step bytes."""
    import numpy as np
    data = np.frombuffer(msg.data, dtype=np.uint8)
    row = msg.width * msg.point_step
    if msg.height > 1 and msg.row_step > row:  # padded rows: drop the padding
        data = data[:msg.height * msg.row_step].reshape(msg.height, msg.row_step)[:, :row]
        data = np.ascontiguousarray(data).reshape(-1)
    if data.size < msg.height * row:
        raise ValueError(f'data holds {data.size} bytes, width * height * point_step is '
                         f'{msg.height * row}')
    return data[:msg.height * row]


def encode_cloud(msg: Any) -> tuple[bytes, dict]:
    """sensor_msgs/PointCloud2 -> float32 xyz of the finite points, then uint8 rgb if the
    cloud has colour, as rviz's default colour transformers give it: `rgb`/`rgba` packed in
    a float32 or uint32 (RGB8), else `intensity` on rviz's rainbow between its min and max."""
    import numpy as np
    fields = {f.name: f for f in msg.fields}
    for axis in 'xyz':
        if axis not in fields or fields[axis].datatype not in POINT_FIELD_TYPES:
            raise ValueError(f'no {axis} field of a numeric type')
    colour = next((name for name in ('rgb', 'rgba', 'intensity') if name in fields
                   and fields[name].datatype in POINT_FIELD_TYPES), None)
    order = '>' if msg.is_bigendian else '<'
    names = ['x', 'y', 'z'] + ([colour] if colour else [])
    formats = [order + POINT_FIELD_TYPES[fields[n].datatype] for n in names]
    if colour in ('rgb', 'rgba'):
        formats[3] = order + 'u4'  # the float32's bits are the packed 0x00RRGGBB
    count = msg.width * msg.height
    if msg.point_step <= 0 or count == 0:
        return b'', {'points': 0, 'color': None}
    try:
        points = np.ndarray((count,), buffer=_packed(msg), dtype=np.dtype(
            {'names': names, 'formats': formats, 'itemsize': msg.point_step,
             'offsets': [fields[n].offset for n in names]}))
    except (TypeError, ValueError) as error:
        raise ValueError(f'fields do not fit point_step {msg.point_step}: {error}') from None
    xyz = np.empty((count, 3), dtype='<f4')
    for i, axis in enumerate('xyz'):
        xyz[:, i] = points[axis]
    finite = np.isfinite(xyz).all(axis=1)
    xyz = xyz[finite]
    if colour in ('rgb', 'rgba'):
        packed = points[colour][finite]
        rgb = np.stack([(packed >> 16) & 255, (packed >> 8) & 255, packed & 255],
                       axis=1).astype(np.uint8)
    elif colour == 'intensity':
        values = points[colour][finite].astype(np.float64)
        valid = values[np.isfinite(values)]
        low, high = (float(valid.min()), float(valid.max())) if valid.size else (0.0, 0.0)
        span = high - low
        normalized = (values - low) / span if span > 0 else np.zeros_like(values)
        rgb = _rainbow(1.0 - normalized)
    else:
        rgb = None
    body = xyz.tobytes() + (rgb.tobytes() if rgb is not None else b'')
    return body, {'points': int(xyz.shape[0]), 'color': colour and ('intensity' if colour ==
                                                                    'intensity' else 'rgb')}


IMAGE_ENCODINGS = {  # encoding: (numpy type, channels)
    'rgb8': ('u1', 3), 'bgr8': ('u1', 3), 'rgba8': ('u1', 4), 'bgra8': ('u1', 4),
    'mono8': ('u1', 1), '8UC1': ('u1', 1), '8UC3': ('u1', 3), '8UC4': ('u1', 4),
    'mono16': ('u2', 1), '16UC1': ('u2', 1), '32FC1': ('f4', 1)}


def encode_image(msg: Any) -> tuple[bytes, dict]:
    """sensor_msgs/Image -> RGBA bytes for a canvas. 16-bit and float images are scaled from
    their min to max, as rviz's Image display does by default (Normalize Range)."""
    import numpy as np
    if msg.encoding not in IMAGE_ENCODINGS:
        raise ValueError(f'encoding {msg.encoding!r} is not drawn (drawn: '
                         f'{", ".join(IMAGE_ENCODINGS)})')
    kind, channels = IMAGE_ENCODINGS[msg.encoding]
    dtype = np.dtype(kind).newbyteorder('>' if msg.is_bigendian else '<')
    width, height = msg.width, msg.height
    row = width * channels * dtype.itemsize
    data = np.frombuffer(msg.data, dtype=np.uint8)
    if msg.step < row or data.size < msg.step * height:
        raise ValueError(f'{data.size} bytes do not hold {height} rows of step {msg.step} '
                         f'({width} x {msg.encoding})')
    rows = data[:msg.step * height].reshape(height, msg.step)[:, :row]
    pixels = np.ascontiguousarray(rows).view(dtype).reshape(height, width, channels)
    if kind != 'u1':
        values = pixels.astype(np.float64)
        finite = values[np.isfinite(values)]
        low, high = (finite.min(), finite.max()) if finite.size else (0.0, 0.0)
        scaled = (values - low) * (255.0 / (high - low)) if high > low else values * 0
        pixels = np.nan_to_num(scaled).clip(0, 255).astype(np.uint8)
    rgba = np.empty((height, width, 4), dtype=np.uint8)
    rgba[..., 3] = 255
    if channels == 1:
        rgba[..., :3] = pixels
    elif msg.encoding.startswith('bgr'):
        rgba[..., :3] = pixels[..., 2::-1]
    else:
        rgba[..., :3] = pixels[..., :3]
    if channels == 4:
        rgba[..., 3] = pixels[..., 3]
    return rgba.tobytes(), {'width': width, 'height': height, 'encoding': msg.encoding}


def _map_palette() -> Any:
    """rviz's "map" colour scheme, indexed by a cell's value as uint8: 0 (free) to 100
    (occupied) white to black, 101-127 green and 128-254 red to yellow (values a map should
    not hold), 255 (-1, unknown) grey-green."""
    import numpy as np
    palette = np.zeros((256, 4), dtype=np.uint8)
    palette[:, 3] = 255
    grey = 255 - (np.arange(101) * 255) // 100
    palette[:101, :3] = grey[:, None]
    palette[101:128] = (0, 255, 0, 255)
    palette[128:255, 0] = 255
    palette[128:255, 1] = (np.arange(127) * 255) // 126
    palette[255] = (0x70, 0x89, 0x86, 255)
    return palette


def encode_map(msg: Any) -> tuple[bytes, dict]:
    """nav_msgs/OccupancyGrid -> RGBA bytes, row 0 at the origin, in rviz's "map" colours;
    the meta gives the size, resolution and the origin's pose in the map's frame."""
    import numpy as np
    width, height = msg.info.width, msg.info.height
    cells = np.asarray(msg.data, dtype=np.int8).view(np.uint8)
    if cells.size != width * height:
        raise ValueError(f'data holds {cells.size} cells, width * height is {width * height}')
    p, q = msg.info.origin.position, msg.info.origin.orientation
    return _map_palette()[cells].tobytes(), {
        'width': width, 'height': height, 'resolution': msg.info.resolution,
        'position': [p.x, p.y, p.z], 'orientation': [q.x, q.y, q.z, q.w]}


STREAMS = {'cloud': ('sensor_msgs/msg/PointCloud2', encode_cloud),
           'image': ('sensor_msgs/msg/Image', encode_image),
           'map': ('nav_msgs/msg/OccupancyGrid', encode_map)}


class Stream:
    """The latest message of one topic, its sequence number, and its encoding (made once)."""

    def __init__(self) -> None:
        self.seq = 0
        self.msg: Any = None
        self.changed = asyncio.Event()
        self.encoded: tuple[int, bytes, dict] | None = None

    def received(self, msg: Any) -> None:  # on the event loop
        self.seq += 1
        self.msg = msg
        self.changed.set()
        self.changed = asyncio.Event()


async def stream_route(request: web.Request) -> web.StreamResponse:
    kind = request.match_info['kind']
    topic = request.query.get('topic', '')
    if kind not in STREAMS or not _absolute_topic(topic):
        raise web.HTTPBadRequest(text=f'topic must be an absolute topic name, got {topic!r}\n')
    try:
        after = int(request.query.get('after', '0'))
    except ValueError:
        raise web.HTTPBadRequest(text='after must be an integer\n') from None
    reliable = request.query.get('reliability', 'Reliable') != 'Best Effort'
    msg_type, encode = STREAMS[kind]
    app = request.app
    streams = app.setdefault('rviz_streams', {})
    stream = streams.get((kind, topic, reliable))
    if stream is None:
        from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
        stream = streams[(kind, topic, reliable)] = Stream()
        # rviz2's display QoS: keep last 5, Reliable unless the display's Topic says Best
        # Effort (a best-effort subscription drops a large cloud when one fragment is lost:
        # 2 of 10 clouds/s arrived here; a best-effort publisher needs it, as in rviz2).
        # A Map display is transient local, as rviz2's: a map published once still arrives.
        qos = QoSProfile(depth=5, reliability=ReliabilityPolicy.RELIABLE if reliable
                         else ReliabilityPolicy.BEST_EFFORT,
                         durability=DurabilityPolicy.TRANSIENT_LOCAL if kind == 'map'
                         else DurabilityPolicy.VOLATILE)
        await app['bridge'].subscribe(topic, msg_type, stream.received, qos=qos)
    if stream.seq <= after:
        try:
            await asyncio.wait_for(stream.changed.wait(), STREAM_WAIT)
        except asyncio.TimeoutError:
            pass
    if stream.seq <= after or stream.msg is None:
        return web.Response(status=204, headers={'X-Rviz': json.dumps({'seq': stream.seq})})
    if stream.encoded is None or stream.encoded[0] != stream.seq:
        seq, msg = stream.seq, stream.msg
        try:
            body, meta = await asyncio.get_running_loop().run_in_executor(None, encode, msg)
        except ValueError as error:
            body, meta = b'', {'error': str(error)}
        meta.update(seq=seq, frame=msg.header.frame_id)
        stream.encoded = (seq, body, meta)
    _, body, meta = stream.encoded
    return web.Response(body=body, content_type='application/octet-stream',
                        headers={'X-Rviz': json.dumps(meta), 'Cache-Control': 'no-store'})


# ------------------------------------------------------------------ tool belt
# rviz2's tools: (default topic, message type). 2D Pose Estimate's covariance is rviz's
# default: 0.5 m standard deviation in x and y, pi/12 in yaw (as float32: 0.0685389...).
TOOLS = {'initialpose': ('/initialpose', 'geometry_msgs/msg/PoseWithCovarianceStamped'),
         'goal': ('/goal_pose', 'geometry_msgs/msg/PoseStamped'),
         'point': ('/clicked_point', 'geometry_msgs/msg/PointStamped')}
INITIAL_POSE_COVARIANCE = {0: 0.25, 7: 0.25, 35: 0.06853891909122467}


def tool_message(tool: str, frame: str, stamp: Any, x: float, y: float, z: float,
                 yaw: float) -> Any:
    from rqt_web.forms import interface_class
    msg = interface_class(TOOLS[tool][1], 'msg')()
    msg.header.frame_id = frame
    msg.header.stamp = stamp
    if tool == 'point':
        msg.point.x, msg.point.y, msg.point.z = x, y, z
        return msg
    pose = msg.pose.pose if tool == 'initialpose' else msg.pose
    pose.position.x, pose.position.y, pose.position.z = x, y, z
    pose.orientation.z, pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    if tool == 'initialpose':
        covariance = [0.0] * 36
        for index, value in INITIAL_POSE_COVARIANCE.items():
            covariance[index] = value
        msg.pose.covariance = covariance
    return msg


async def tool_route(request: web.Request) -> web.Response:
    try:
        body = await request.json()
        tool = str(body.get('tool'))
        topic = str(body.get('topic') or TOOLS[tool][0])
        frame = str(body.get('frame', ''))
        x, y, z, yaw = (float(body.get(k, 0.0)) for k in ('x', 'y', 'z', 'yaw'))
        if not all(math.isfinite(v) for v in (x, y, z, yaw)):
            raise ValueError('x, y, z and yaw must be finite numbers')
        if not frame or len(frame) > MAX_TOPIC or not _absolute_topic(topic):
            raise ValueError('frame must be a frame id and topic an absolute topic name')
    except (ValueError, TypeError, KeyError, AttributeError, OverflowError) as error:
        raise web.HTTPBadRequest(text=f'tool must be one of {", ".join(TOOLS)} with finite '
                                 f'x, y, z, yaw: {error}\n') from None
    bridge = request.app['bridge']
    stamp = await bridge.run(lambda: bridge.node.get_clock().now().to_msg())
    msg = tool_message(tool, frame, stamp, x, y, z, yaw)
    try:
        await bridge.publish(topic, TOOLS[tool][1], msg)
    except Exception as error:  # rclpy refusing the topic name
        raise web.HTTPBadRequest(text=f'cannot publish on {topic}: {error}\n') from None
    return web.json_response({'published': True, 'topic': topic, 'type': TOOLS[tool][1]})


async def config_route(request: web.Request) -> web.Response:
    try:
        return web.json_response(read_rviz(request.query.get('path', '')))
    except ValueError as error:
        raise web.HTTPBadRequest(text=f'{error}\n') from None


async def description_route(request: web.Request) -> web.Response:
    topic = request.query.get('topic', '/robot_description')
    if not _absolute_topic(topic):
        raise web.HTTPBadRequest(text=f'topic must be an absolute topic name, got {topic!r}\n')
    app = request.app
    if 'rviz_descriptions' not in app:
        app['rviz_descriptions'] = DescriptionFeed(app['bridge'])
    feed = app['rviz_descriptions']
    await app['bridge'].run(lambda: feed.subscribe(topic))
    count, text = feed.latest[topic]
    return web.json_response({'topic': topic, 'count': count, 'urdf': text})


def resolve_resource(uri: str) -> Path:
    if uri.startswith('package://'):
        package, _, relative = uri[len('package://'):].partition('/')
        from ament_index_python.packages import PackageNotFoundError, get_package_share_directory
        try:
            path = Path(get_package_share_directory(package)) / relative
        except PackageNotFoundError:
            raise ValueError(f'package [{package}] of {uri} not found') from None
    elif uri.startswith('file://'):
        path = Path(uri[len('file://'):])
    else:
        raise ValueError(f'uri must start with package:// or file://, got {uri!r}')
    if path.suffix.lower() not in RESOURCE_SUFFIXES:
        raise ValueError(f'{uri}: only {", ".join(RESOURCE_SUFFIXES)} files are served')
    if not path.is_file():
        raise ValueError(f'{uri}: no such file ({os.fspath(path)})')
    return path


async def resource_route(request: web.Request) -> web.StreamResponse:
    try:
        return web.FileResponse(resolve_resource(request.query.get('uri', '')))
    except ValueError as error:
        raise web.HTTPNotFound(text=f'{error}\n') from None


def add_routes(app: web.Application) -> None:
    app.router.add_routes([
        web.get('/api/rviz/config', config_route),
        web.get('/api/rviz/description', description_route),
        web.get('/api/rviz/markers', markers_route),
        web.get('/api/rviz/latest', latest_route),
        web.get('/api/rviz/resource', resource_route),
        web.get('/api/rviz/{kind:cloud|image|map}', stream_route),
        web.post('/api/rviz/tool', tool_route)])
