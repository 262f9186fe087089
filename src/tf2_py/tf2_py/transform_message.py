"""Build the TransformStamped a lookup returns, fast.

The generated message constructors build every nested default and check every field, which
costs ~11 us per TransformStamped: more than the lookup itself. Our values are floats, ints
and strings by construction, so the messages are assembled from their slots directly. The
generated slot names are checked once at import against a normally built message; if a
rosidl version ever changes them, the normal constructors are used.
"""
from builtin_interfaces.msg import Time
from geometry_msgs.msg import Quaternion, Transform, TransformStamped, Vector3
from std_msgs.msg import Header

_new = object.__new__
_CHECK_FIELDS = getattr(Vector3(), '_check_fields', True)  # as a normally built message


def _from_slots(values: tuple, stamp: int, target: str, source: str) -> TransformStamped:
    time = _new(Time)
    time._sec, time._nanosec = divmod(stamp, 1_000_000_000)
    header = _new(Header)
    header._stamp, header._frame_id = time, target
    translation = _new(Vector3)
    translation._x, translation._y, translation._z = values[0], values[1], values[2]
    rotation = _new(Quaternion)
    rotation._x, rotation._y, rotation._z, rotation._w = values[3], values[4], values[5], values[6]
    transform = _new(Transform)
    transform._translation, transform._rotation = translation, rotation
    message = _new(TransformStamped)
    message._header, message._child_frame_id, message._transform = header, source, transform
    for part in (time, header, translation, rotation, transform, message):
        part._check_fields = _CHECK_FIELDS
    return message


def _from_constructors(values: tuple, stamp: int, target: str,
                       source: str) -> TransformStamped:
    sec, nanosec = divmod(stamp, 1_000_000_000)
    return TransformStamped(
        header=Header(stamp=Time(sec=sec, nanosec=nanosec), frame_id=target),
        child_frame_id=source,
        transform=Transform(
            translation=Vector3(x=values[0], y=values[1], z=values[2]),
            rotation=Quaternion(x=values[3], y=values[4], z=values[5], w=values[6])))


def _slots_match() -> bool:
    sample = ((1.0, 2.0, 3.0, 0.0, 0.6, 0.0, 0.8), 1_500_000_007, 'parent', 'child')
    try:
        return _from_slots(*sample) == _from_constructors(*sample)
    except AttributeError:
        return False


transform_stamped = _from_slots if _slots_match() else _from_constructors
"""transform_stamped((x, y, z, qx, qy, qz, qw), stamp_ns, frame_id, child_frame_id)."""
