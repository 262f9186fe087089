"""launch.utilities: helpers shared by actions, substitutions and front ends (upstream's)."""

from launch.utilities.class_tools_impl import is_a, is_a_subclass, isclassinstance
from launch.utilities.ensure_argument_type_impl import ensure_argument_type
from launch.utilities.normalize_to_list_of_entities_impl import normalize_to_list_of_entities
from launch.utilities.normalize_to_list_of_substitutions_impl import (
    normalize_to_list_of_substitutions,
)
from launch.utilities.perform_substitutions_impl import perform_substitutions
from launch.utilities.signal_management import AsyncSafeSignalManager
from launch.utilities.visit_all_entities_and_collect_futures_impl import (
    visit_all_entities_and_collect_futures,
)

__all__ = [
    'AsyncSafeSignalManager', 'ensure_argument_type', 'is_a', 'is_a_subclass',
    'isclassinstance', 'normalize_to_list_of_entities', 'normalize_to_list_of_substitutions',
    'perform_substitutions', 'visit_all_entities_and_collect_futures',
]
