"""BufferInterface: transform() of stamped types through registered conversions."""
from collections.abc import Callable
from typing import Any, ClassVar

from geometry_msgs.msg import TransformStamped
from rclpy.duration import Duration
from std_msgs.msg import Header

DoTransform = Callable[[Any, TransformStamped], Any]
NO_WAIT = Duration()  # the default timeout: answer from what is in the buffer now


class TypeException(Exception):
    """A type with no registered transform or conversion."""

    def __init__(self, errstr: str) -> None:
        super().__init__(errstr)
        self.errstr = errstr


class NotImplementedException(Exception):
    def __init__(self) -> None:
        super().__init__('CanTransform or LookupTransform not implemented')
        self.errstr = 'CanTransform or LookupTransform not implemented'


class TransformRegistration:
    """Which function transforms each stamped type (tf2_geometry_msgs registers its own)."""

    _type_map: ClassVar[dict[type, DoTransform]] = {}

    def add(self, key: type, callback: DoTransform) -> None:
        TransformRegistration._type_map[key] = callback

    def get(self, key: type) -> DoTransform:
        if key not in TransformRegistration._type_map:
            raise TypeException(f'Type {key} is not loaded or supported')
        return TransformRegistration._type_map[key]


class ConvertRegistration:
    """Conversions between stamped types, for transform(..., new_type=...)."""

    _to_msg: ClassVar[dict[type, Callable[[Any], Any]]] = {}
    _from_msg: ClassVar[dict[type, Callable[[Any], Any]]] = {}
    _convert: ClassVar[dict[tuple[type, type], Callable[[Any], Any]]] = {}

    def add_from_msg(self, key: type, callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._from_msg[key] = callback

    def add_to_msg(self, key: type, callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._to_msg[key] = callback

    def add_convert(self, key: tuple[type, type], callback: Callable[[Any], Any]) -> None:
        ConvertRegistration._convert[key] = callback

    def get_from_msg(self, key: type) -> Callable[[Any], Any]:
        if key not in ConvertRegistration._from_msg:
            raise TypeException(f'Type {key} if not loaded or supported')
        return ConvertRegistration._from_msg[key]

    def get_to_msg(self, key: type) -> Callable[[Any], Any]:
        if key not in ConvertRegistration._to_msg:
            raise TypeException(f'Type {key} if not loaded or supported')
        return ConvertRegistration._to_msg[key]

    def get_convert(self, key: tuple[type, type]) -> Callable[[Any], Any]:
        if key not in ConvertRegistration._convert:
            raise TypeException(f'Type {key} if not loaded or supported')
        return ConvertRegistration._convert[key]


def convert(a: Any, b_type: type) -> Any:
    """`a` as a `b_type`, through a registered direct conversion or through messages."""
    registration = ConvertRegistration()
    try:
        return registration.get_convert((type(a), b_type))(a)
    except TypeException:
        return registration.get_from_msg(b_type)(registration.get_to_msg(type(a))(a))


def Stamped(obj: Any, stamp: Any, frame_id: str) -> Any:
    obj.header = Header(frame_id=frame_id, stamp=stamp)
    return obj


class BufferInterface:
    """transform()/transform_full() on top of a subclass's lookup_transform(_full)."""

    def __init__(self) -> None:
        self.registration = TransformRegistration()

    def transform(self, object_stamped: Any, target_frame: str,
                  timeout: Duration = NO_WAIT, new_type: type | None = None) -> Any:
        """`object_stamped` (any registered stamped type) expressed in target_frame."""
        do_transform = self.registration.get(type(object_stamped))
        result = do_transform(object_stamped, self.lookup_transform(
            target_frame, object_stamped.header.frame_id, object_stamped.header.stamp, timeout))
        return result if new_type is None else convert(result, new_type)

    def transform_full(self, object_stamped: Any, target_frame: str, target_time: Any,
                       fixed_frame: str, timeout: Duration = NO_WAIT,
                       new_type: type | None = None) -> Any:
        do_transform = self.registration.get(type(object_stamped))
        result = do_transform(object_stamped, self.lookup_transform_full(
            target_frame, target_time, object_stamped.header.frame_id,
            object_stamped.header.stamp, fixed_frame, timeout))
        return result if new_type is None else convert(result, new_type)

    def lookup_transform(self, target_frame: str, source_frame: str, time: Any,
                         timeout: Duration = NO_WAIT) -> TransformStamped:
        raise NotImplementedException()

    def lookup_transform_full(self, target_frame: str, target_time: Any, source_frame: str,
                              source_time: Any, fixed_frame: str,
                              timeout: Duration = NO_WAIT) -> TransformStamped:
        raise NotImplementedException()

    def can_transform(self, target_frame: str, source_frame: str, time: Any,
                      timeout: Duration = NO_WAIT) -> bool:
        raise NotImplementedException()

    def can_transform_full(self, target_frame: str, target_time: Any, source_frame: str,
                           source_time: Any, fixed_frame: str,
                           timeout: Duration = NO_WAIT) -> bool:
        raise NotImplementedException()
