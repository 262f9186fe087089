"""tf2's exceptions, with upstream's Python classes (tf2_py) and messages (tf2's C++ core)."""


class TransformException(Exception):
    """Base of every tf2 error: catch this to handle any failed lookup."""


class ConnectivityException(TransformException):
    """The two frames are in different trees."""


class LookupException(TransformException):
    """A frame does not exist, or the tree has a loop."""


class ExtrapolationException(TransformException):
    """The requested time is outside the cached data (past, future, or a single sample)."""


class InvalidArgumentException(TransformException):
    """An empty or '/'-prefixed frame id."""


class TimeoutException(TransformException):
    """A wait for a transform ran out of time."""


# tf2's error codes (tf2_msgs/TF2Error and tf2's C++ enum; the three extrapolation kinds are
# one ExtrapolationException in Python, as in tf2_py).
NO_ERROR = 0
LOOKUP_ERROR = 1
CONNECTIVITY_ERROR = 2
EXTRAPOLATION_ERROR = 3
INVALID_ARGUMENT_ERROR = 4
TIMEOUT_ERROR = 5
TRANSFORM_ERROR = 6

EXCEPTION_OF_ERROR = {
    LOOKUP_ERROR: LookupException,
    CONNECTIVITY_ERROR: ConnectivityException,
    EXTRAPOLATION_ERROR: ExtrapolationException,
    INVALID_ARGUMENT_ERROR: InvalidArgumentException,
    TIMEOUT_ERROR: TimeoutException,
    TRANSFORM_ERROR: TransformException,
}
