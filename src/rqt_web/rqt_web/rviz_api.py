"""Server side of the RViz page: its routes, and the JSON it reads of ROS.

TF comes from `tf_feed` (one tf2_ros Buffer for the whole app); .rviz files and meshes from
`rviz_files`; PointCloud2, Image and Map displays from `rviz_streams`. Here:

- GET /api/rviz/description?topic=/robot_description: the latest std_msgs/String on that
  topic (transient local, as robot_state_publisher latches it) and a counter that grows with
  each new one, so the page reloads the model only when it changed.
- GET /api/rviz/markers?topic=/visualization_marker[&type=Marker|MarkerArray]: the markers
  alive now (ADD/MODIFY replace by namespace and id, DELETE and DELETEALL remove, lifetime
  expires), each as JSON with its frame, pose, scale, colour, points and text.
- GET /api/rviz/latest?topic=T&type=pkg/msg/Type: the latest message on T as JSON (Pose,
  PoseArray, Path, Odometry and LaserScan displays), null before the first.
- POST /api/rviz/tool {tool: initialpose|goal|point, topic, frame, x, y, z, yaw}: what the
  tool belt's 2D Pose Estimate, 2D Goal Pose and Publish Point publish, stamped now.

`add_routes` registers these and the routes of `rviz_files`, `rviz_streams` and
`rviz_nav2`.
"""

from __future__ import annotations

import array
import math
import time
from typing import Any

from aiohttp import web

from rqt_web import rviz_nav2
from rqt_web.forms import MAX_TOPIC, absolute_topic, interface_class, message_to_ordered_value
from rqt_web.rviz_files import config_route, resource_route
from rqt_web.rviz_streams import stream_route


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


async def description_route(request: web.Request) -> web.Response:
    topic = request.query.get('topic', '/robot_description')
    if not absolute_topic(topic):
        raise web.HTTPBadRequest(text=f'topic must be an absolute topic name, got {topic!r}\n')
    app = request.app
    if 'rviz_descriptions' not in app:
        app['rviz_descriptions'] = DescriptionFeed(app['bridge'])
    feed = app['rviz_descriptions']
    await app['bridge'].run(lambda: feed.subscribe(topic))
    count, text = feed.latest[topic]
    return web.json_response({'topic': topic, 'count': count, 'urdf': text})


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
    if not absolute_topic(topic) or kind not in ('Marker', 'MarkerArray'):
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
    if not absolute_topic(topic) or kind not in LATEST_TYPES:
        raise web.HTTPBadRequest(text=f'topic must be an absolute topic name and type one of '
                                 f'{", ".join(LATEST_TYPES)}, got {topic!r}, {kind!r}\n')
    app = request.app
    latest = app.setdefault('rviz_latest', {})
    if (topic, kind) not in latest:
        latest[(topic, kind)] = None

        def received(msg: Any) -> None:
            latest[(topic, kind)] = msg
        await app['bridge'].subscribe(topic, kind, received)
    msg = latest[(topic, kind)]
    return web.json_response({'topic': topic, 'msg': None if msg is None
                              else _finite(message_to_ordered_value(msg))})


def _finite(value: Any) -> Any:
    """NaN and +-inf as null: JSON has no such numbers (a LaserScan's out-of-range readings
    are inf, and the page's JSON.parse refused the whole answer)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple, array.array)):
        return [_finite(v) for v in value]
    return value


# ------------------------------------------------------------------ tool belt
# rviz2's tools: (default topic, message type). 2D Pose Estimate's covariance is rviz's
# default: 0.5 m standard deviation in x and y, pi/12 in yaw (as float32: 0.0685389...).
TOOLS = {'initialpose': ('/initialpose', 'geometry_msgs/msg/PoseWithCovarianceStamped'),
         'goal': ('/goal_pose', 'geometry_msgs/msg/PoseStamped'),
         'point': ('/clicked_point', 'geometry_msgs/msg/PointStamped')}
INITIAL_POSE_COVARIANCE = {0: 0.25, 7: 0.25, 35: 0.06853891909122467}


def tool_message(tool: str, frame: str, stamp: Any, x: float, y: float, z: float,
                 yaw: float) -> Any:
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
        if not frame or len(frame) > MAX_TOPIC or not absolute_topic(topic):
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


def add_routes(app: web.Application) -> None:
    # Every /api/rviz/ route in one table, the files' and the streams' too.
    app.router.add_routes([
        web.get('/api/rviz/config', config_route),
        web.get('/api/rviz/description', description_route),
        web.get('/api/rviz/markers', markers_route),
        web.get('/api/rviz/latest', latest_route),
        web.get('/api/rviz/resource', resource_route),
        web.get('/api/rviz/{kind:cloud|image|map}', stream_route),
        web.post('/api/rviz/tool', tool_route)])
    rviz_nav2.add_routes(app)  # ParticleCloud, Nav2 Goal, the Navigation 2 panel
