"""check_is_list_entity(): is a get_attr data_type a request for nested entities?"""

from typing import Any

from launch.utilities.type_utils import is_typing_list


def check_is_list_entity(data_type: Any) -> bool:
    from launch.frontend.entity import Entity
    return is_typing_list(data_type) and getattr(data_type, '__args__', (None,))[0] is Entity
