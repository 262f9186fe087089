"""tf for the web app's pages (TF Tree, RViz): one tf2_ros Buffer fed by /tf and /tf_static.

The buffer and its TransformListener live on the bridge's node and are spun by the bridge's
executor (no thread of their own). They are created when a page first asks, so a server
that never shows tf never subscribes to it. Calls run on the ROS thread (`RosBridge.run`),
as the listener's callbacks do, so the buffer is never read mid-update; except the RViz
page's poses, read on the event loop under the buffer's lock, which the listener holds for
a whole message (two thread hops fewer per answer, and no wait behind queued /tf messages).

Python API (for server code; `feed = await tf_feed.get(app)`):

- `await feed.frames()`: `{child: {'parent', 'broadcaster', 'rate', 'buffer_length',
  'most_recent_transform', 'oldest_transform'}}`, tf2's `all_frames_as_yaml` parsed: what
  view_frames and rqt_tf_tree draw on each edge (static frames: rate 10000, times 0).
- `await feed.lookup(frame, fixed_frame)`: `frame`'s pose in `fixed_frame` at the latest
  common time, `{'frame', 'fixed_frame', 'stamp', 'translation': [x, y, z],
  'rotation': [x, y, z, w]}`, or `{'frame', 'fixed_frame', 'error': tf2's message}`.
- `await feed.poses(fixed_frame)`: `lookup` of every known frame (and `fixed_frame`).
- `feed.poses_and_parents(fixed_frame)`: `(version, poses, parents)` read together (any thread);
  `parents` is `{child: parent}` of every frame with a transform (its latest parent).
- `feed.version`: grows with every /tf or /tf_static message and each clear;
  `await feed.wait_newer(after, timeout)` returns as soon as it is above `after`.
- `await feed.clear()`: forget everything (rqt_tf_tree's "Clear buffer").

HTTP (token-checked like every route): GET /api/tf/frames, GET /api/tf/lookup?frame=&
fixed_frame=, GET /api/tf/poses?fixed_frame=[&after=N], POST /api/tf/clear. The poses answer
also gives `parents` and `version`; with `after`, it waits (up to TF_WAIT) until the version
is above N: the RViz page keeps one such request open and hears of a new message at once
instead of at its next poll.
"""

from __future__ import annotations

import asyncio
import time
from typing import Any

import yaml
from aiohttp import web

FRAME_FIELDS = ('parent', 'broadcaster', 'rate', 'buffer_length', 'most_recent_transform',
                'oldest_transform')
MAX_FRAME_ID = 256  # characters of a frame id a request may name
TF_WAIT = 1.0  # seconds a poses request with `after` waits for newer tf data


_LOADER = getattr(yaml, 'CSafeLoader', yaml.SafeLoader)


class TfFeed:
    def __init__(self, bridge: Any) -> None:
        """Create the buffer and listener; call on the ROS thread (see `get`)."""
        import tf2_ros
        self.bridge = bridge
        # No node= here: the server's node offers no services to the graph (tf2_frames).
        self.buffer = tf2_ros.Buffer()
        # Written on the ROS thread only; read on the event loop (an int: no torn reads).
        self.version = 0
        # Requests waiting for a newer version (event loop side). The ROS thread wakes the
        # loop only while some wait: 50+ /tf messages a second cost nothing otherwise.
        self._waiters = 0
        self._newer = asyncio.Event()
        feed = self

        class Listener(tf2_ros.TransformListener):
            # One wake-up per message (not per transform: 107 per message in the bench).
            def callback(self, data: Any) -> None:
                # A reader under the lock sees whole messages, and the version that has them.
                with feed.buffer._lock:
                    super().callback(data)
                    feed._bump()

            def static_callback(self, data: Any) -> None:
                with feed.buffer._lock:
                    super().static_callback(data)
                    feed._bump()
        self.listener = Listener(self.buffer, bridge.node, spin_thread=False)

    # ------------------------------------------------------------ on the ROS thread
    def _frames(self) -> dict[str, dict]:
        # libyaml's loader: PyYAML's pure-Python one took 31 ms for 107 frames, twice per
        # RViz poll, and held the ROS thread (the page's latency grew to ~220 ms).
        data = yaml.load(self.buffer.all_frames_as_yaml(), Loader=_LOADER) or {}
        return {str(child): {field: info.get(field) for field in FRAME_FIELDS}
                for child, info in data.items() if isinstance(info, dict)}

    def _lookup(self, frame: str, fixed_frame: str) -> dict:
        import rclpy.time
        from tf2_ros import TransformException
        try:
            t = self.buffer.lookup_transform(fixed_frame, frame, rclpy.time.Time())
        except TransformException as error:
            return {'frame': frame, 'fixed_frame': fixed_frame, 'error': str(error)}
        translation, rotation = t.transform.translation, t.transform.rotation
        return {'frame': frame, 'fixed_frame': fixed_frame,
                'stamp': t.header.stamp.sec + t.header.stamp.nanosec * 1e-9,
                'translation': [translation.x, translation.y, translation.z],
                'rotation': [rotation.x, rotation.y, rotation.z, rotation.w]}

    def _bump(self) -> None:
        self.version += 1
        # The waiter counts itself before it reads the version (wait_newer): either it sees
        # this version or this sees it waiting, so no message is left unannounced.
        if self._waiters:
            self.bridge.loop.call_soon_threadsafe(self._wake)

    def _parents(self) -> dict[str, str]:
        # Each frame's latest parent straight from tf2_py's caches (the Python BufferCore of
        # this workspace): the RViz page's TF lines without all_frames_as_yaml and a second
        # request per poll (3.6 ms of YAML for 107 frames, and a request the page waited for).
        with self.buffer._lock:
            return {child: cache.latest()[1] for child, cache in self.buffer._caches.items()
                    if cache is not None and len(cache)}

    def _clear(self) -> None:
        with self.buffer._lock:
            self.buffer.clear()
            self._bump()

    def _poses(self, fixed_frame: str) -> dict[str, dict]:
        # Every frame tf2 knows, parents included (tf2_py's and upstream's _getFrameStrings):
        # no YAML round trip on each of the page's polls.
        names = set(self.buffer._getFrameStrings()) | {fixed_frame}
        return {name: self._lookup(name, fixed_frame) for name in sorted(names)}

    # ------------------------------------------------------------ from the event loop
    async def frames(self) -> dict[str, dict]:
        return await self.bridge.run(self._frames)

    async def lookup(self, frame: str, fixed_frame: str) -> dict:
        return await self.bridge.run(lambda: self._lookup(frame, fixed_frame))

    async def poses(self, fixed_frame: str) -> dict[str, dict]:
        return await self.bridge.run(lambda: self._poses(fixed_frame))

    def poses_and_parents(self, fixed_frame: str) -> tuple[int, dict, dict]:
        """(version, poses, parents), read together on the calling thread: tf2_py's lock
        (re-entrant) is held throughout, and by the listener for each message it stores."""
        with self.buffer._lock:
            return self.version, self._poses(fixed_frame), self._parents()

    async def wait_newer(self, after: int, timeout: float) -> None:
        self._waiters += 1
        try:
            if self.version > after:
                return
            try:
                await asyncio.wait_for(self._newer.wait(), timeout)
            except asyncio.TimeoutError:
                pass
        finally:
            self._waiters -= 1

    def _wake(self) -> None:  # on the event loop
        self._newer.set()
        self._newer = asyncio.Event()

    async def clear(self) -> None:
        await self.bridge.run(self._clear)


async def get(app: web.Application) -> TfFeed:
    """The app's feed, created (and subscribed) on first use."""
    lock = app.setdefault('tf_feed_lock', asyncio.Lock())
    async with lock:
        if 'tf_feed' not in app:
            bridge = app['bridge']
            app['tf_feed'] = await bridge.run(lambda: TfFeed(bridge))
    return app['tf_feed']


def _frame_id(request: web.Request, name: str, default: str | None = None) -> str:
    value = request.query.get(name, default)
    if not value or len(value) > MAX_FRAME_ID:
        raise web.HTTPBadRequest(text=f'{name} must be a frame id of 1 to {MAX_FRAME_ID} '
                                 f'characters, got {value!r}\n')
    return value


async def frames_route(request: web.Request) -> web.Response:
    feed = await get(request.app)
    return web.json_response({'frames': await feed.frames(), 'time': time.time()})


async def lookup_route(request: web.Request) -> web.Response:
    frame = _frame_id(request, 'frame')
    fixed_frame = _frame_id(request, 'fixed_frame', 'world')
    feed = await get(request.app)
    return web.json_response(await feed.lookup(frame, fixed_frame))


async def poses_route(request: web.Request) -> web.Response:
    fixed_frame = _frame_id(request, 'fixed_frame', 'world')
    after = request.query.get('after')
    if after is not None:
        try:
            after = int(after)
        except ValueError:
            raise web.HTTPBadRequest(text=f'after must be an integer, got {after!r}\n') from None
    feed = await get(request.app)
    if after is not None:
        await feed.wait_newer(after, TF_WAIT)
    version, poses, parents = feed.poses_and_parents(fixed_frame)
    return web.json_response({'fixed_frame': fixed_frame, 'poses': poses, 'parents': parents,
                              'version': version, 'time': time.time()})


async def clear_route(request: web.Request) -> web.Response:
    feed = await get(request.app)
    await feed.clear()
    return web.json_response({'cleared': True})


def add_routes(app: web.Application) -> None:
    app.router.add_routes([
        web.get('/api/tf/frames', frames_route), web.get('/api/tf/lookup', lookup_route),
        web.get('/api/tf/poses', poses_route), web.post('/api/tf/clear', clear_route)])
