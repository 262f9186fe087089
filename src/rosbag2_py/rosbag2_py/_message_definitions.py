"""LocalMessageDefinitionSource: a type's full definition from the installed interface files."""

from __future__ import annotations

from rosbag2_py._definitions import full_text
from rosbag2_py._storage import MessageDefinition


class LocalMessageDefinitionSource:
    def get_full_text(self, topic_type: str) -> MessageDefinition:
        encoding, text = full_text(topic_type)
        return MessageDefinition(topic_type, encoding or 'unknown', text, '')
