"""The generated class of a rosidl_parser NamespacedType."""

from __future__ import annotations

import importlib
import warnings
from typing import Any

from rosidl_parser.definition import NamespacedType

FEEDBACK_MESSAGE_SUFFIX = '_FeedbackMessage'


def import_message_from_namespaced_type(message_type: NamespacedType) -> Any:
    """Import the class `message_type` names (e.g. (['std_msgs', 'msg'], 'String')).

    A nested type (a sequence of messages) is still accepted for its element type, with a
    DeprecationWarning, as older callers passed one.
    """
    if not isinstance(message_type, NamespacedType) and hasattr(message_type, 'value_type'):
        message_type = message_type.value_type
        warnings.warn('Passing objects containing a NamespacedType is deprecated, please pass '
                      'a NamespacedType object directly', DeprecationWarning, stacklevel=2)
    parts = [*message_type.namespaces, message_type.name]
    if not all(part.isidentifier() for part in parts):
        # Else importlib's own error: a TypeError for '..' (a relative import), for instance.
        raise ValueError(f"'{'/'.join(parts)}' is not an interface type: expected "
                         '<package>/<msg|srv|action>/<Name>')
    module = importlib.import_module('.'.join(message_type.namespaces))
    if message_type.name.endswith(FEEDBACK_MESSAGE_SUFFIX):
        # An action's feedback message is not a module attribute but the action's Impl's.
        action, name = message_type.name.rsplit('_', 1)
        return getattr(getattr(module, action).Impl, name)
    return getattr(module, message_type.name)
