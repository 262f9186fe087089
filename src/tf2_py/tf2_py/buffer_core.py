"""BufferCore: tf2's frame graph and lookups, as upstream's C++ core behaves (tf2_py's API).

Times are rclpy Time/Duration (anything with `nanoseconds`) or builtin_interfaces messages
(`sec`, `nanosec`); time 0 means "the latest time every frame on the path has".
"""
import threading
from typing import Any

import rclpy.duration
import rclpy.time
from geometry_msgs.msg import TransformStamped
from tf2_py.core_log import ERROR, WARN, log
from tf2_py.exceptions import (
    CONNECTIVITY_ERROR,
    EXCEPTION_OF_ERROR,
    LOOKUP_ERROR,
    NO_ERROR,
    InvalidArgumentException,
    LookupException,
    TransformException,
)
from tf2_py.maths import IDENTITY, Transform, compose, inverse
from tf2_py.time_cache import Entry, StaticCache, TimeCache, display_time, is_finite
from tf2_py.transform_message import transform_stamped
from tf2_py.velocity import Twist, lookup_velocity

DEFAULT_CACHE_TIME = 10_000_000_000  # ns, tf2's BUFFER_CORE_DEFAULT_CACHE_TIME
MAX_GRAPH_DEPTH = 1000
QUATERNION_NORMALIZATION_TOLERANCE = 10e-3




def nanoseconds(time: Any) -> int:
    """Nanoseconds of an rclpy Time/Duration or a builtin_interfaces Time/Duration."""
    value = getattr(time, 'nanoseconds', None)
    if value is not None:
        return value
    try:
        return time.sec * 1_000_000_000 + time.nanosec
    except AttributeError:
        raise TypeError('time must have sec and nanosec, or nanoseconds.') from None


class BufferCore:
    """Transforms between frames over the last `cache_time` (default 10 s), thread-safe."""

    def __init__(self, cache_time: Any = None) -> None:
        self._max_age = DEFAULT_CACHE_TIME if cache_time is None else nanoseconds(cache_time)
        # Every frame ever named, in order of appearance; None for a frame that is only a
        # parent (a root), else its cache.
        self._caches: dict[str, TimeCache | StaticCache | None] = {}
        self._authority: dict[str, str] = {}
        self._lock = threading.RLock()

    def get_cache_length(self) -> Any:
        return rclpy.duration.Duration(nanoseconds=self._max_age)

    # --- input ----------------------------------------------------------------------------
    # Both return None, as upstream's binding does (a refused transform is logged, not told).
    def set_transform(self, transform: TransformStamped, authority: str) -> None:
        self._set(transform, authority, False)

    def set_transform_static(self, transform: TransformStamped, authority: str) -> None:
        self._set(transform, authority, True)

    def _set(self, transform: TransformStamped, authority: str, is_static: bool) -> bool:
        parent = transform.header.frame_id.lstrip('/')
        child = transform.child_frame_id.lstrip('/')
        t, q = transform.transform.translation, transform.transform.rotation
        entry: Entry = (parent, t.x, t.y, t.z, q.x, q.y, q.z, q.w)
        if not self._valid(entry, child, authority):
            return False
        stamp = nanoseconds(transform.header.stamp)  # a Time message or an rclpy Time
        with self._lock:
            cache = self._caches.get(child)
            if cache is None or cache.is_static != is_static:
                cache = StaticCache(entry) if is_static else TimeCache(self._max_age)
                self._caches[child] = cache
            self._caches.setdefault(parent, None)
            if not cache.insert(stamp, entry):
                log(WARN,
                     f'TF_OLD_DATA ignoring data from the past for frame {child} at time '
                     f'{display_time(stamp)} according to authority {authority}\nPossible '
                     'reasons are listed at http://wiki.ros.org/tf/Errors%20explained')
                return False
            self._authority[child] = authority
        return True

    @staticmethod
    def _valid(entry: Entry, child: str, authority: str) -> bool:
        """tf2's checks on incoming transforms, with its messages: one error line each."""
        parent = entry[0]
        valid = True
        if child == parent:
            log(ERROR, f'TF_SELF_TRANSFORM: Ignoring transform from authority "{authority}" '
                          f'with frame_id and  child_frame_id "{child}" because they are the same')
            valid = False
        if not child:
            log(ERROR, f'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority '
                          f'"{authority}" because child_frame_id not set ')
            valid = False
        if not parent:
            log(ERROR, f'TF_NO_FRAME_ID: Ignoring transform with child_frame_id "{child}"  '
                          f'from authority "{authority}" because frame_id not set')
            valid = False
        x, y, z, qx, qy, qz, qw = entry[1:]
        if not is_finite(entry):
            log(ERROR,
                f'TF_NAN_INPUT: Ignoring transform for child_frame_id "{child}" from authority '
                f'"{authority}" because of a nan value in the transform ({x:f} {y:f} {z:f}) '
                f'({qx:f} {qy:f} {qz:f} {qw:f})')
            return False
        if abs(qw * qw + qx * qx + qy * qy + qz * qz - 1.0) >= QUATERNION_NORMALIZATION_TOLERANCE:
            log(ERROR,
                f'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "{child}" '
                f'from authority "{authority}" because of an invalid quaternion in the '
                f'transform ({qx:f} {qy:f} {qz:f} {qw:f})')
            valid = False
        return valid

    def clear(self) -> None:
        """Forget every dynamic transform; static frames stay, as in tf2."""
        with self._lock:
            for cache in self._caches.values():
                if cache is not None:
                    cache.clear()

    # --- lookups --------------------------------------------------------------------------
    def lookup_transform_core(self, target_frame: str, source_frame: str,
                              time: Any) -> TransformStamped:
        """The transform taking data in source_frame to target_frame at `time`."""
        transform, stamp = self._lookup(target_frame, source_frame, nanoseconds(time))
        return transform_stamped(transform, stamp, target_frame, source_frame)

    def lookup_transform_full_core(self, target_frame: str, target_time: Any,
                                   source_frame: str, source_time: Any,
                                   fixed_frame: str) -> TransformStamped:
        """source_frame at source_time to target_frame at target_time, through fixed_frame
        (a frame assumed not to move between the two times: "time travel")."""
        with self._lock:
            for name, frame in (('target_frame', target_frame), ('source_frame', source_frame),
                                ('fixed_frame', fixed_frame)):
                self._validate(f'lookupTransform argument {name}', frame)
            source_in_fixed, _ = self._lookup(fixed_frame, source_frame, nanoseconds(source_time))
            fixed_in_target, stamp = self._lookup(target_frame, fixed_frame,
                                                  nanoseconds(target_time))
        return transform_stamped(compose(fixed_in_target, source_in_fixed), stamp,
                                 target_frame, source_frame)

    def can_transform_core(self, target_frame: str, source_frame: str,
                           time: Any) -> tuple[bool, str]:
        """(whether lookup_transform_core would succeed, why not)."""
        if target_frame == source_frame:
            return True, ''
        with self._lock:
            error = (self._check('canTransform argument target_frame', target_frame)
                     or self._check('canTransform argument source_frame', source_frame))
            if error:
                return False, error
            code, message, _, _ = self._walk(target_frame, source_frame, nanoseconds(time))
        return code == NO_ERROR, message

    def can_transform_full_core(self, target_frame: str, target_time: Any, source_frame: str,
                                source_time: Any, fixed_frame: str) -> tuple[bool, str]:
        with self._lock:
            for name, frame in (('target_frame', target_frame), ('source_frame', source_frame),
                                ('fixed_frame', fixed_frame)):
                error = self._check(f'canTransform argument {name}', frame)
                if error:
                    return False, error
            for target, source, time in ((target_frame, fixed_frame, target_time),
                                         (fixed_frame, source_frame, source_time)):
                if target != source:
                    code, message, _, _ = self._walk(target, source, nanoseconds(time))
                    if code != NO_ERROR:
                        return False, message
        return True, ''

    def get_latest_common_time(self, target_frame: str, source_frame: str) -> rclpy.time.Time:
        with self._lock:
            self._validate('get_latest_common_time', target_frame)
            self._validate('get_latest_common_time', source_frame)
            code, message, time = self._latest_common_time(target_frame, source_frame)
        if code != NO_ERROR:
            raise TransformException(message)
        return rclpy.time.Time(nanoseconds=time)

    # --- velocity (tf2's lookupVelocity; the tuples upstream's binding returns) ------------
    def lookupVelocityCore(self, tracking_frame: str, observation_frame: str, time: Any,
                           averaging_interval: Any) -> Twist:
        """((vx, vy, vz), (wx, wy, wz)) of tracking_frame seen from observation_frame."""
        return self.lookupVelocityFullCore(tracking_frame, observation_frame, observation_frame,
                                           (0.0, 0.0, 0.0), tracking_frame, time,
                                           averaging_interval)

    def lookupVelocityFullCore(self, tracking_frame: str, observation_frame: str,
                               reference_frame: str, reference_point: tuple,
                               reference_point_frame: str, time: Any,
                               averaging_interval: Any) -> Twist:
        with self._lock:
            code, _, latest = self._latest_common_time(observation_frame, tracking_frame)
            return lookup_velocity(
                lambda target, source, at: self._lookup(target, source, at)[0],
                latest if code == NO_ERROR else 0, tracking_frame, observation_frame,
                reference_frame, tuple(float(c) for c in reference_point),
                reference_point_frame, nanoseconds(time), nanoseconds(averaging_interval))

    # --- introspection --------------------------------------------------------------------
    def all_frames_as_yaml(self, current_time: Any = None) -> str:
        """Every frame with parent, broadcaster, rate and times, in tf2's YAML (tf2_frames)."""
        now = 0 if current_time is None else nanoseconds(current_time)
        lines = []
        with self._lock:
            for frame, cache in self._caches.items():
                if cache is None or not len(cache):
                    continue
                latest, oldest = cache.latest_stamp(), cache.oldest_stamp()
                rate = len(cache) * 1e9 / max(latest - oldest, 100_000)
                lines += [f'{frame}: ',
                          f"  parent: '{cache.latest()[1]}'",
                          f"  broadcaster: '{self._authority.get(frame, 'no recorded authority')}'",
                          f'  rate: {rate:.3f}',
                          f'  most_recent_transform: {display_time(latest)}',
                          f'  oldest_transform: {display_time(oldest)}']
                if now:
                    lines.append(f'  transform_delay: {(now - latest) / 1e9:.3f}')
                lines.append(f'  buffer_length: {(latest - oldest) / 1e9:.3f}')
        return '\n'.join(lines) + '\n' if lines else '[]'

    def all_frames_as_string(self) -> str:
        with self._lock:
            return ''.join(f'Frame {frame} exists with parent {cache.latest()[1] or "NO_PARENT"}.\n'
                           for frame, cache in self._caches.items() if cache is not None)

    def _frameExists(self, frame_id: str) -> bool:
        return frame_id in self._caches

    def _getFrameStrings(self) -> list[str]:
        with self._lock:
            return list(self._caches)

    # --- internals ------------------------------------------------------------------------
    def _check(self, argument: str, frame: str) -> str:
        """canTransform's wording for a bad frame id, or '' when the frame is known."""
        if not frame:
            rationale = 'in tf2 frame_ids cannot be empty'
        elif frame.startswith('/'):
            rationale = "in tf2 frame_ids cannot start with a '/'"
        elif frame not in self._caches:
            rationale = 'frame does not exist'
        else:
            return ''
        return f'Invalid frame ID "{frame}" passed to {argument} - {rationale}'

    def _validate(self, argument: str, frame: str) -> None:
        """lookupTransform's checks: raise as tf2 does for a bad or unknown frame id."""
        if frame in self._caches:
            return
        if not frame:
            raise InvalidArgumentException(
                f'Invalid argument "{frame}" passed to {argument} - in tf2 frame_ids cannot '
                'be empty')
        if frame.startswith('/'):
            raise InvalidArgumentException(
                f'Invalid argument "{frame}" passed to {argument} - in tf2 frame_ids cannot '
                "start with a '/'")
        raise LookupException(f'"{frame}" passed to {argument} does not exist. ')

    def _lookup(self, target: str, source: str, time: int) -> tuple[Transform, int]:
        with self._lock:
            if target == source:
                cache = self._caches.get(target) if time == 0 else None
                return IDENTITY, cache.latest_stamp() if cache is not None else time
            self._validate('lookupTransform argument target_frame', target)
            self._validate('lookupTransform argument source_frame', source)
            code, message, transform, stamp = self._walk(target, source, time)
        if code != NO_ERROR:
            raise EXCEPTION_OF_ERROR[code](message)
        return transform, stamp

    def _walk(self, target: str, source: str, time: int) -> tuple[int, str, Transform, int]:
        """tf2's walkToTopParent: accumulate source->root and target->root until they meet.
        Returns (error code, message, target_T_source, time used)."""
        if time == 0:
            code, message, time = self._latest_common_time(target, source)
            if code != NO_ERROR:
                return code, message, IDENTITY, 0
        caches = self._caches
        # source -> top: s is the source frame expressed in `frame`, updated link by link.
        sx = sy = sz = sqx = sqy = sqz = 0.0
        sqw = 1.0
        frame = source
        depth = 0
        source_failure = None
        while True:
            cache = caches.get(frame)
            if cache is None:
                break
            entry = cache.data_at(time)
            if entry is None:
                source_failure = cache.explain(time)
                break
            if frame == target:  # target is an ancestor of source
                return NO_ERROR, '', (sx, sy, sz, sqx, sqy, sqz, sqw), time
            parent, x, y, z, qx, qy, qz, qw = entry
            tx = 2.0 * (qy * sz - qz * sy)  # rotate (sx, sy, sz) by q, then translate
            ty = 2.0 * (qz * sx - qx * sz)
            tz = 2.0 * (qx * sy - qy * sx)
            sx, sy, sz = (sx + qw * tx + qy * tz - qz * ty + x,
                          sy + qw * ty + qz * tx - qx * tz + y,
                          sz + qw * tz + qx * ty - qy * tx + z)
            sqx, sqy, sqz, sqw = (qw * sqx + qx * sqw + qy * sqz - qz * sqy,
                                  qw * sqy - qx * sqz + qy * sqw + qz * sqx,
                                  qw * sqz + qx * sqy - qy * sqx + qz * sqw,
                                  qw * sqw - qx * sqx - qy * sqy - qz * sqz)
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LOOKUP_ERROR, self._loop_message(), IDENTITY, time
        top = frame
        # target -> top, the same way.
        ux = uy = uz = uqx = uqy = uqz = 0.0
        uqw = 1.0
        frame = target
        depth = 0
        while frame != top:
            cache = caches.get(frame)
            if cache is None:
                break
            entry = cache.data_at(time)
            if entry is None:
                code, message = cache.explain(time)
                return code, f'{message}{self._between(source, target)}', IDENTITY, time
            if frame == source:  # source is an ancestor of target
                return NO_ERROR, '', inverse((ux, uy, uz, uqx, uqy, uqz, uqw)), time
            parent, x, y, z, qx, qy, qz, qw = entry
            tx = 2.0 * (qy * uz - qz * uy)
            ty = 2.0 * (qz * ux - qx * uz)
            tz = 2.0 * (qx * uy - qy * ux)
            ux, uy, uz = (ux + qw * tx + qy * tz - qz * ty + x,
                          uy + qw * ty + qz * tx - qx * tz + y,
                          uz + qw * tz + qx * ty - qy * tx + z)
            uqx, uqy, uqz, uqw = (qw * uqx + qx * uqw + qy * uqz - qz * uqy,
                                  qw * uqy - qx * uqz + qy * uqw + qz * uqx,
                                  qw * uqz + qx * uqy - qy * uqx + qz * uqw,
                                  qw * uqw - qx * uqx - qy * uqy - qz * uqz)
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LOOKUP_ERROR, self._loop_message(), IDENTITY, time
        if frame != top:
            if source_failure is not None:
                code, message = source_failure
                return code, f'{message}{self._between(source, target)}', IDENTITY, time
            return CONNECTIVITY_ERROR, self._unconnected(source, target), IDENTITY, time
        return NO_ERROR, '', compose(inverse((ux, uy, uz, uqx, uqy, uqz, uqw)),
                                     (sx, sy, sz, sqx, sqy, sqz, sqw)), time

    def _latest_common_time(self, target: str, source: str) -> tuple[int, str, int]:
        """tf2's getLatestCommonTime: the newest time every dynamic link between the frames
        has data for (0 when the path is all static). Returns (error code, message, time)."""
        if source == target:
            cache = self._caches.get(source)
            return NO_ERROR, '', cache.latest_stamp() if cache is not None else 0
        caches = self._caches
        never = 1 << 63
        # source -> root: (stamp, parent) of every link.
        source_links: list[tuple[int, str]] = []
        common = never
        frame = source
        while True:
            cache = caches.get(frame)
            if cache is None:
                break
            stamp, parent = cache.latest()
            if parent is None:
                break
            if stamp:
                common = min(common, stamp)
            source_links.append((stamp, parent))
            frame = parent
            if frame == target:
                return NO_ERROR, '', 0 if common == never else common
            if len(source_links) > MAX_GRAPH_DEPTH:
                return LOOKUP_ERROR, self._loop_message(), 0
        # target -> root, until a parent the source side passed through.
        source_parents = {parent for _, parent in source_links}
        common = never
        common_parent = None
        frame = target
        depth = 0
        while True:
            cache = caches.get(frame)
            if cache is None:
                break
            stamp, parent = cache.latest()
            if parent is None:
                break
            if stamp:
                common = min(common, stamp)
            if parent in source_parents:
                common_parent = parent
                break
            frame = parent
            if frame == source:
                return NO_ERROR, '', 0 if common == never else common
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                return LOOKUP_ERROR, self._loop_message(), 0
        if common_parent is None:
            return CONNECTIVITY_ERROR, self._unconnected(source, target), 0
        for stamp, parent in source_links:
            if stamp:
                common = min(common, stamp)
            if parent == common_parent:
                break
        return NO_ERROR, '', 0 if common == never else common

    def _between(self, source: str, target: str) -> str:
        return f', when looking up transform from frame [{source}] to frame [{target}]'

    def _unconnected(self, source: str, target: str) -> str:
        return (f"Could not find a connection between '{target}' and '{source}' because they "
                'are not part of the same tree.Tf has two or more unconnected trees.')

    def _loop_message(self) -> str:
        return ('The tf tree is invalid because it contains a loop.\n'
                f'{self.all_frames_as_string()}\n')

