"""to_parameters_list: evaluated parameters as rclpy Parameters for one node (what a
composable node's load request carries)."""

from __future__ import annotations

import pathlib
import warnings
from collections.abc import Sequence
from typing import Any

import rclpy.parameter
import yaml

from launch_ros.utilities.evaluate_parameters import evaluate_parameter_dict
from launch_ros.utilities.normalize_parameters import normalize_parameter_dict


def _by_node(document: Any) -> dict[str, dict[str, Any]]:
    """{'ns/node': parameters} of a parameters file ('/**' read as '**')."""
    found: dict[str, dict[str, Any]] = {}

    def walk(mapping: dict[str, Any], keys: list[str]) -> None:
        for key, value in mapping.items():
            if key == 'ros__parameters':
                found['/'.join(keys)] = value
                return
            if isinstance(value, dict):
                walk(value, [*keys, key.lstrip('/')])

    if isinstance(document, dict):
        walk(document, [])
    return found


def to_parameters_list(context: Any, node_name: str, namespace: str,
                       evaluated_parameters: Sequence[Any]) -> list[rclpy.parameter.Parameter]:
    name = node_name.lstrip('/')
    if namespace and namespace != '/':
        name = f"{namespace.strip('/')}/{name}"
    parameters: list[rclpy.parameter.Parameter] = []
    warned = False
    for item in evaluated_parameters:
        values: Any = item
        if isinstance(item, pathlib.Path):
            with open(item) as handle:
                document = yaml.safe_load(handle)
            per_node = _by_node(document)
            if per_node:
                values = dict(per_node.get('**', {}))
                values.update(per_node.get(name, {}))
                if not node_name and not warned:
                    warnings.warn('node name not provided to launch; parameter files will '
                                  'not apply', UserWarning, stacklevel=2)
                    warned = True
            else:
                values = document or {}
            values = evaluate_parameter_dict(context, normalize_parameter_dict(values)) \
                if values else {}
        if not isinstance(values, dict):
            raise RuntimeError(f'invalid evaluated parameters {values!r}')
        for key, value in values.items():
            kind = next((t for t in rclpy.parameter.Parameter.Type if t.check(value)), None)
            if kind is None:
                raise RuntimeError(f'invalid parameter value {value!r}')
            parameters.append(rclpy.parameter.Parameter(key, kind, value))
    return parameters
