"""launch: start and supervise processes described by launch files (upstream's Python API).

A small asyncio implementation of the parts of ROS 2's `launch` that courses and tutorials
use; see docs/launch.md for what is supported and where it differs.
"""

import os

from launch import (
                    actions,
                    conditions,
                    event_handlers,
                    events,
                    launch_description_sources,
                    logging,
                    substitutions,
)
from launch._missing import module_getattr
from launch.action import Action
from launch.condition import Condition
from launch.event import Event
from launch.event_handler import BaseEventHandler, EventHandler
from launch.launch_context import LaunchContext
from launch.launch_description import LaunchDescription
from launch.launch_description_entity import LaunchDescriptionEntity
from launch.launch_description_sources import LaunchDescriptionSource
from launch.launch_introspector import LaunchIntrospector
from launch.launch_service import LaunchService
from launch.substitution import (
                    SomeSubstitutionsType,
                    SomeSubstitutionsType_types_tuple,
                    Substitution,
)

__all__ = [
    'Action', 'BaseEventHandler', 'Condition', 'Event', 'EventHandler', 'LaunchContext',
    'LaunchDescription', 'LaunchDescriptionEntity', 'LaunchDescriptionSource',
    'LaunchIntrospector', 'LaunchService', 'SomeSubstitutionsType',
    'SomeSubstitutionsType_types_tuple', 'Substitution', 'actions', 'conditions',
    'event_handlers', 'events', 'launch_description_sources', 'logging', 'substitutions',
]

__getattr__ = module_getattr(__name__, os.path.dirname(__file__))
