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
"""

from __future__ import annotations

import os
import time
from pathlib import Path
from typing import Any

import yaml
from aiohttp import web

RESOURCE_SUFFIXES = ('.stl', '.dae', '.obj', '.mtl', '.png', '.jpg', '.jpeg')
MAX_TOPIC = 256


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
    return {'path': path, 'fixed_frame': str(options.get('Fixed Frame', 'map')),
            'background': rgb, 'displays': [_display(d) for d in manager.get('Displays') or []
                                            if isinstance(d, dict)],
            'view': {k: views.get(k) for k in ('Class', 'Distance', 'Pitch', 'Yaw', 'Scale',
                                                 'X', 'Y')}}


def _display(d: dict) -> dict:
    topic = d.get('Topic')
    if isinstance(topic, dict):
        topic = topic.get('Value')
    description = d.get('Description Topic')
    if isinstance(description, dict):
        topic = description.get('Value', topic)
    return {'class': str(d.get('Class', '')), 'name': str(d.get('Name', '')),
            'enabled': bool(d.get('Value', True)), 'topic': topic,
            'alpha': d.get('Alpha', 1), 'settings': {k: v for k, v in d.items()
                                                     if isinstance(v, (str, int, float, bool))}}


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
                'mesh': m.mesh_resource,
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
    if not topic.startswith('/') or len(topic) > MAX_TOPIC or kind not in ('Marker',
                                                                           'MarkerArray'):
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
    if not topic.startswith('/') or len(topic) > MAX_TOPIC or kind not in LATEST_TYPES:
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


async def config_route(request: web.Request) -> web.Response:
    try:
        return web.json_response(read_rviz(request.query.get('path', '')))
    except ValueError as error:
        raise web.HTTPBadRequest(text=f'{error}\n') from None


async def description_route(request: web.Request) -> web.Response:
    topic = request.query.get('topic', '/robot_description')
    if not topic.startswith('/') or len(topic) > MAX_TOPIC:
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
        web.get('/api/rviz/resource', resource_route)])
