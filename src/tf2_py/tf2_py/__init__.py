"""tf2_py: tf2's BufferCore and exceptions in pure Python (upstream's module of that name
wraps tf2's C++ core; the API, behaviour and messages here are the same)."""
from tf2_py.buffer_core import BufferCore
from tf2_py.exceptions import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)

__all__ = ['BufferCore', 'ConnectivityException', 'ExtrapolationException',
           'InvalidArgumentException', 'LookupException', 'TimeoutException',
           'TransformException']
