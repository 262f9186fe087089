"""Front-end typing: nested-entity requests and `type="..."` identifiers."""

from typing import Any

from launch.utilities.type_utils import is_typing_list


def check_is_list_entity(data_type: Any) -> bool:
    from launch.frontend.entity import Entity
    return is_typing_list(data_type) and getattr(data_type, '__args__', (None,))[0] is Entity


# A <param type="..."> as get_attr's data_type; 'yaml' (None) reads the value as YAML does.
_IDENTIFIED_TYPES = {'str': str, 'bool': bool, 'float': float, 'int': int,
                     'list_of_str': list[str], 'list_of_bool': list[bool],
                     'list_of_float': list[float], 'list_of_int': list[int], 'yaml': None}


def get_data_type_from_identifier(type_identifier: str) -> Any:
    if type_identifier not in _IDENTIFIED_TYPES:
        raise ValueError(f"Got invalid type identifier '{type_identifier}' (allowed: "
                         f"{', '.join(_IDENTIFIED_TYPES)})")
    return _IDENTIFIED_TYPES[type_identifier]
