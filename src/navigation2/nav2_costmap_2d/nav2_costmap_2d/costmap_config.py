"""A LayeredCostmap from a costmap's parameters, as Costmap2DROS configures one.

Takes the `ros__parameters` of a Nav2 params file's `global_costmap` or `local_costmap` as they
stand (nested mappings) or as a node holds them (flattened "layer.name" keys), with upstream's
defaults: plugins ["static_layer", "obstacle_layer", "inflation_layer"], width and height 5 m,
resolution 0.1, robot_radius 0.1, footprint "[]", footprint_padding 0.01, ...
A `nav2_costmap_2d::VoxelLayer` runs as the 2-D ObstacleLayer (its z parameters are ignored).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from nav2_costmap_2d.costmap_layer import Layer, ParameterError, read_parameter
from nav2_costmap_2d.footprint import FootprintError, footprint_from_parameters
from nav2_costmap_2d.inflation_layer import InflationLayer
from nav2_costmap_2d.layered_costmap import LayeredCostmap
from nav2_costmap_2d.obstacle_layer import ObstacleLayer
from nav2_costmap_2d.static_layer import StaticLayer

DEFAULT_PLUGINS = {'static_layer': 'nav2_costmap_2d::StaticLayer',
                   'obstacle_layer': 'nav2_costmap_2d::ObstacleLayer',
                   'inflation_layer': 'nav2_costmap_2d::InflationLayer'}
LAYER_TYPES: dict[str, type[Layer]] = {
    'StaticLayer': StaticLayer,
    'ObstacleLayer': ObstacleLayer,
    'VoxelLayer': ObstacleLayer,  # 2-D here: voxels flattened to the obstacle grid
    'InflationLayer': InflationLayer,
}
# Costmap2DROS' own parameters and their defaults (types as upstream declares them).
COSTMAP_PARAMETERS: dict[str, Any] = {
    'always_send_full_costmap': False, 'map_vis_z': 0.0, 'footprint_padding': 0.01,
    'footprint': '[]', 'global_frame': 'map', 'height': 5, 'width': 5,
    'lethal_cost_threshold': 100, 'observation_sources': '', 'origin_x': 0.0, 'origin_y': 0.0,
    'publish_frequency': 1.0, 'resolution': 0.1, 'robot_base_frame': 'base_link',
    'robot_radius': 0.1, 'rolling_window': False, 'track_unknown_space': False,
    'transform_tolerance': 0.3, 'initial_transform_timeout': 60.0, 'trinary_costmap': True,
    'unknown_cost_value': 255, 'update_frequency': 5.0, 'use_maximum': False,
    'map_topic': 'map',
}


def unflatten(params: Mapping[str, Any]) -> dict[str, Any]:
    """{'a.b': 1, 'c': {'d': 2}} -> {'a': {'b': 1}, 'c': {'d': 2}}."""
    tree: dict[str, Any] = {}
    for key, value in params.items():
        if isinstance(value, Mapping):
            value = unflatten(value)
        node = tree
        *parents, leaf = str(key).split('.')
        for part in parents:
            node = node.setdefault(part, {})
        if isinstance(value, dict) and isinstance(node.get(leaf), dict):
            node[leaf].update(value)
        else:
            node[leaf] = value
    return tree


@dataclass
class CostmapConfig:
    """A configured layered costmap and the parameters it was made from."""

    name: str
    layered: LayeredCostmap
    settings: dict[str, Any]
    plugin_types: dict[str, str]
    used_radius: bool = True
    messages: list[str] = field(default_factory=list)  # upstream's ERROR/WARN lines

    def layer(self, name: str) -> Layer:
        return next(plugin for plugin in self.layered.plugins if plugin.name == name)


def build_costmap(params: Mapping[str, Any], name: str = 'costmap') -> CostmapConfig:
    """Costmap2DROS::on_configure without the ROS parts: layers, size and footprint."""
    tree = unflatten(params)
    settings = {key: read_parameter(tree, name, key, default)
                for key, default in COSTMAP_PARAMETERS.items()}
    if not settings['resolution'] > 0:
        raise ParameterError(f"{name}.resolution: must be > 0, got {settings['resolution']}")
    plugin_names = tree.get('plugins', list(DEFAULT_PLUGINS))
    if not isinstance(plugin_names, list | tuple) or not all(
            isinstance(plugin, str) for plugin in plugin_names):
        raise ParameterError(f'{name}.plugins: expected a list of layer names, '
                             f'got {plugin_names!r}')
    messages: list[str] = []
    layered = LayeredCostmap(settings['global_frame'], settings['rolling_window'],
                             settings['track_unknown_space'])
    for key, side in (('width', 'width'), ('height', 'height')):
        if settings[key] <= 0:
            messages.append(f'You try to set {side} of map to be negative or zero, this '
                            "isn't allowed, please give a positive value.")
    layered.resize_map(max(0, int(settings['width'] / settings['resolution'])),
                       max(0, int(settings['height'] / settings['resolution'])),
                       settings['resolution'], settings['origin_x'], settings['origin_y'])
    plugin_types: dict[str, str] = {}
    for plugin in plugin_names:
        layer_params = tree.get(plugin) or {}
        if not isinstance(layer_params, Mapping):
            raise ParameterError(f'{name}.{plugin}: expected the layer\'s parameters, '
                                 f'got {layer_params!r}')
        plugin_type = layer_params.get('plugin', DEFAULT_PLUGINS.get(plugin))
        if not isinstance(plugin_type, str):
            raise ParameterError(f"{name}.{plugin}.plugin: no plugin type given for '{plugin}'")
        cls = LAYER_TYPES.get(plugin_type.replace('::', '/').split('/')[-1])
        if cls is None or not plugin_type.startswith('nav2_costmap_2d'):
            raise ParameterError(f'{name}.{plugin}.plugin: Failed to create plugin {plugin} '
                                 f"of type {plugin_type}: not one of nav2_costmap_2d's "
                                 f"{', '.join(sorted(LAYER_TYPES))}")
        plugin_types[plugin] = plugin_type
        if cls is InflationLayer:
            layer = InflationLayer(plugin, layered, layer_params)
        else:
            layer = cls(plugin, layered, layer_params, settings)  # type: ignore[call-arg]
        layered.add_plugin(layer)
    used_radius = True
    try:
        footprint, used_radius = footprint_from_parameters(
            settings['footprint'], settings['robot_radius'], settings['footprint_padding'])
    except FootprintError as error:
        messages.append(str(error))
        messages.append(f"The footprint parameter is invalid: \"{settings['footprint']}\", "
                        f"using radius ({settings['robot_radius']:f}) instead")
        footprint, used_radius = footprint_from_parameters(
            '[]', settings['robot_radius'], settings['footprint_padding'])
    layered.set_footprint(footprint)
    for plugin in layered.plugins:
        messages.extend(getattr(plugin, 'warnings', []))
    return CostmapConfig(name, layered, settings, plugin_types, used_radius, messages)
