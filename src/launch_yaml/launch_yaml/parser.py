"""Reads a YAML launch file into launch.frontend entities.

`launch:` holds a list of one-key mappings (`- node: {...}`); a mapping's keys are attributes,
except `children` and the lists of `arg`, `remap`, `param`, `env`, `keep`, which are children.
"""

from __future__ import annotations

from typing import Any

import yaml
from launch.frontend import Entity, FrontendError

from launch import frontend

_YAML_LIST_CHILDREN = {'arg', 'remap', 'param', 'env', 'keep'}


def _from_yaml(tag: str, body: Any) -> Entity:
    if isinstance(body, list):  # e.g. `group:` directly followed by its actions
        return Entity(tag, {}, [_from_yaml_item(item) for item in body])
    if not isinstance(body, dict):
        raise FrontendError(f"'{tag}' must hold a mapping of attributes, got {body!r}")
    attributes: dict[str, Any] = {}
    children: list[Entity] = []
    for key, value in body.items():
        if key == 'children':
            children += [_from_yaml_item(item) for item in value or []]
        elif key in _YAML_LIST_CHILDREN and isinstance(value, list):
            children += [_from_yaml(key, item) for item in value]
        else:
            attributes[key] = value
    return Entity(tag, attributes, children)


def _from_yaml_item(item: Any) -> Entity:
    if not isinstance(item, dict) or len(item) != 1:
        raise FrontendError(f'each launch entry must be one action (e.g. `- node: ...`), got '
                            f'{item!r}')
    ((tag, body),) = item.items()
    return _from_yaml(str(tag), body)


class Parser(frontend.Parser):
    file_extensions = ('yaml', 'yml')

    @classmethod
    def load(cls, path: str) -> Entity:
        with open(path, encoding='utf-8') as handle:
            try:
                data = yaml.safe_load(handle)
            except yaml.YAMLError as error:
                raise FrontendError(f'invalid YAML: {error}'.replace('\n', ' ')) from None
        if not isinstance(data, dict) or 'launch' not in data:
            raise FrontendError("a YAML launch file starts with 'launch:'")
        return Entity('launch', {}, [_from_yaml_item(item) for item in data['launch'] or []])
