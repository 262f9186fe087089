"""The RViz page's long-polled binary streams: PointCloud2, Image and Map displays.

GET /api/rviz/cloud?topic=T&after=N, /api/rviz/image?topic=T&after=N and
/api/rviz/map?topic=T&after=N (a map transient local, &scheme=map|costmap|raw its Color
Scheme; &reliability=Best Effort as the display's Topic QoS, else reliable): the latest
message newer than the page's N, waited for up to STREAM_WAIT (204 No Content if none
came), as the binary `rviz_encoding` makes, once per message however many pages ask. The
`X-Rviz` header gives JSON: seq, frame, points or width/height (a map: resolution, origin),
colour.
"""

from __future__ import annotations

import asyncio
import functools
import json
from typing import Any

from aiohttp import web

from rqt_web.forms import absolute_topic
from rqt_web.rviz_encoding import MAP_SCHEMES, encode_cloud, encode_image, encode_map

STREAM_WAIT = 1.0  # seconds a page's request waits for a newer message

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
    if kind not in STREAMS or not absolute_topic(topic):
        raise web.HTTPBadRequest(text=f'topic must be an absolute topic name, got {topic!r}\n')
    try:
        after = int(request.query.get('after', '0'))
    except ValueError:
        raise web.HTTPBadRequest(text='after must be an integer\n') from None
    scheme = request.query.get('scheme', 'map')
    if scheme not in MAP_SCHEMES:
        raise web.HTTPBadRequest(text=f'scheme must be one of {", ".join(MAP_SCHEMES)}, '
                                 f'got {scheme!r}\n')
    reliable = request.query.get('reliability', 'Reliable') != 'Best Effort'
    msg_type, encode = STREAMS[kind]
    if kind == 'map':
        encode = functools.partial(encode_map, scheme=scheme)
    app = request.app
    streams = app.setdefault('rviz_streams', {})
    key = (kind, topic, reliable, scheme if kind == 'map' else '')
    stream = streams.get(key)
    if stream is None:
        from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
        stream = streams[key] = Stream()
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
