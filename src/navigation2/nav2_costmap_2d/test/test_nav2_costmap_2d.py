"""nav2_costmap_2d's pure maths: grid conversions, footprints, layers and their combination.

Known answers come from Nav2's formulas worked by hand (inflation: 252 * exp(-k (d - r_in)),
truncated), the costmap publisher's translation table and upstream's Bresenham walk.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from nav2_costmap_2d.clear_costmap import clear_entirely, clear_region
from nav2_costmap_2d.cost_values import (
    FREE_SPACE,
    INSCRIBED_INFLATED_OBSTACLE,
    LETHAL_OBSTACLE,
    NO_INFORMATION,
)
from nav2_costmap_2d.costmap_2d import Costmap2D, costs_to_occupancy
from nav2_costmap_2d.costmap_config import build_costmap
from nav2_costmap_2d.costmap_layer import ParameterError
from nav2_costmap_2d.footprint import (
    FootprintError,
    calculate_min_and_max_distances,
    footprint_from_parameters,
    make_footprint_from_string,
)
from nav2_costmap_2d.inflation_layer import InflationLayer
from nav2_costmap_2d.layered_costmap import LayeredCostmap
from nav2_costmap_2d.obstacle_layer import ObstacleLayer
from nav2_costmap_2d.raytrace import raytrace_cells
from nav2_costmap_2d.static_layer import StaticLayer, interpret_values

SQUARE = '[[0.2, 0.2], [0.2, -0.2], [-0.2, -0.2], [-0.2, 0.2]]'


def test_world_map_conversions_follow_nav2():
    grid = Costmap2D(100, 50, 0.05, -2.0, -1.0)
    assert grid.world_to_map(-2.0, -1.0) == (0, 0)
    assert grid.world_to_map(0.024, 0.074) == (40, 21)  # truncation toward the origin
    assert grid.world_to_map(-2.001, 0.0) is None
    assert grid.world_to_map(3.0, 0.0) is None  # x = 100 cells: one past the last
    assert grid.map_to_world(0, 0) == pytest.approx((-1.975, -0.975))
    assert grid.world_to_map_enforce_bounds(-9.0, 9.0) == (0, 49)
    assert grid.cell_distance(0.55) == 11
    assert grid.cell_distance(0.551) == 12  # rounded up
    assert grid.cell_distance(0.5) == 10
    assert grid.occupancy_origin() == pytest.approx((-2.0, -1.0))


def test_occupancy_translation_is_the_costmap_publishers():
    costs = np.array([0, 1, 2, 100, 126, 252, 253, 254, 255], dtype=np.uint8)
    assert costs_to_occupancy(costs).tolist() == [0, 1, 1, 39, 49, 98, 99, 100, -1]


def test_footprint_string_and_radius():
    assert make_footprint_from_string(SQUARE) == [(0.2, 0.2), (0.2, -0.2), (-0.2, -0.2),
                                                  (-0.2, 0.2)]
    assert calculate_min_and_max_distances(make_footprint_from_string(SQUARE)) == \
        pytest.approx((0.2, math.hypot(0.2, 0.2)))
    padded, used_radius = footprint_from_parameters('[]', 0.22, 0.0)
    assert used_radius and len(padded) == 16
    # the 16-gon's inscribed radius is the distance to its edges
    assert calculate_min_and_max_distances(padded)[0] == pytest.approx(
        0.22 * math.cos(math.pi / 16))
    padded, used_radius = footprint_from_parameters(SQUARE, 0.5, 0.01)
    assert not used_radius and padded[0] == pytest.approx((0.21, 0.21))


@pytest.mark.parametrize(('text', 'message'), [
    ('[[0.1, 0.1], [0.1, -0.1]]', 'at least three points'),
    ('[[0.1, 0.1], [0.1], [0.2, 0.2]]', 'Found a point with 1 numbers'),
    ('[[0.1, 0.1], [0.1, -0.1], [-0.1, 0.1]', 'Unterminated vector string'),
    ('[[[0.1]]]', 'Array depth greater than 2'),
    ('0.1, 0.2', "Numbers at depth other than 2. Char was '0'"),
    ('[[0.1, x], [1, 1], [2, 2]]', "Expected a number. Char was 'x'"),
])
def test_malformed_footprints_are_refused_in_one_line(text, message):
    with pytest.raises(FootprintError) as error:
        make_footprint_from_string(text)
    assert message in str(error.value) and '\n' not in str(error.value)


def test_static_layer_interprets_values_as_nav2():
    data = np.array([0, 50, 99, 100, -1], dtype=np.int8)
    assert interpret_values(data, 100, 255, True, True).tolist() == [0, 0, 0, 254, 255]
    assert interpret_values(data, 100, 255, True, False).tolist() == [0, 0, 0, 254, 0]
    # not trinary: value / threshold * 254, truncated
    assert interpret_values(data, 100, 255, False, True).tolist() == [0, 127, 251, 254, 255]
    assert interpret_values(data, 65, 255, True, True).tolist() == [0, 0, 254, 254, 255]


def _layered(track_unknown: bool = True, rolling: bool = False,
             footprint: str = SQUARE) -> LayeredCostmap:
    layered = LayeredCostmap('map', rolling, track_unknown)
    layered.resize_map(60, 60, 0.05, 0.0, 0.0)
    layered.set_footprint(footprint_from_parameters(footprint, 0.22, 0.0)[0])
    return layered


def test_inflation_costs_at_known_distances():
    layered = _layered()
    static = StaticLayer('static_layer', layered, {}, {'track_unknown_space': True})
    inflation = InflationLayer('inflation_layer', layered,
                               {'inflation_radius': 0.55, 'cost_scaling_factor': 3.0})
    layered.add_plugin(static)
    layered.add_plugin(inflation)
    layered.set_footprint(make_footprint_from_string(SQUARE))  # inscribed radius 0.2 m
    grid = np.zeros((60, 60), dtype=np.int8)
    grid[30, 30] = 100
    static.process_map(60, 60, 0.05, 0.0, 0.0, grid.ravel())
    layered.update_map(1.0, 1.0, 0.0)
    cost = layered.costmap.costmap
    assert cost[30, 30] == LETHAL_OBSTACLE
    assert cost[30, 34] == INSCRIBED_INFLATED_OBSTACLE  # 0.20 m: inside the inscribed radius
    assert cost[30, 35] == 216  # 0.25 m: int(252 * exp(-3 * 0.05))
    assert cost[34, 33] == 216  # (3, 4) cells is 0.25 m too
    assert cost[30, 40] == 102  # 0.50 m: int(252 * exp(-3 * 0.30))
    assert cost[30, 41] == 88  # 0.55 m: the last cell within the inflation radius
    assert cost[30, 42] == FREE_SPACE  # 12 cells: beyond it
    assert cost[30 + 7, 30 + 6] == int(252 * math.exp(-3.0 * (math.hypot(6, 7) * 0.05 - 0.2)))


def test_inflation_keeps_unknown_unless_inscribed():
    layered = _layered()
    static = StaticLayer('static_layer', layered, {}, {'track_unknown_space': True})
    layered.add_plugin(static)
    layered.add_plugin(InflationLayer('inflation_layer', layered,
                                      {'inflation_radius': 0.55, 'cost_scaling_factor': 3.0}))
    layered.set_footprint(make_footprint_from_string(SQUARE))
    grid = np.full((60, 60), -1, dtype=np.int8)
    grid[30, 30] = 100
    static.process_map(60, 60, 0.05, 0.0, 0.0, grid.ravel())
    layered.update_map(1.0, 1.0, 0.0)
    cost = layered.costmap.costmap
    assert cost[30, 33] == INSCRIBED_INFLATED_OBSTACLE  # unknown overwritten when inscribed
    assert cost[30, 36] == NO_INFORMATION  # a lower cost leaves the unknown cell unknown
    assert costs_to_occupancy(cost)[30, 36] == -1


def test_update_with_max_combines_as_nav2():
    layered = _layered()
    static = StaticLayer('static_layer', layered, {}, {'track_unknown_space': True})
    obstacles = ObstacleLayer('obstacle_layer', layered, {}, {'track_unknown_space': True})
    master = layered.costmap
    master.costmap[:] = [[NO_INFORMATION, 10, 200][i % 3] for i in range(60)]
    obstacles.costmap[:] = NO_INFORMATION
    obstacles.costmap[:, :30] = 100
    obstacles.update_with_max(master)
    row = master.costmap[0]
    assert row[:6].tolist() == [100, 100, 200, 100, 100, 200]  # unknown and lower cells raised
    assert row[30:33].tolist() == [NO_INFORMATION, 10, 200]  # the layer's unknown changes nothing
    del static


def _scan_layer(layered: LayeredCostmap, **source: object) -> ObstacleLayer:
    params = {'observation_sources': 'scan',
              'scan': {'topic': '/scan', 'marking': True, 'clearing': True, **source}}
    layer = ObstacleLayer('obstacle_layer', layered, params, {'track_unknown_space': True})
    layered.add_plugin(layer)
    return layer


def test_scan_marks_endpoints_and_raytracing_clears_them():
    layered = _layered()
    layer = _scan_layer(layered, obstacle_max_range=2.5, raytrace_max_range=3.0)
    # one beam straight ahead (+x) from (0.51, 1.525): an obstacle 1 m away
    layer.add_scan('scan', [1.0], 0.0, 0.01, 0.1, 10.0, (0.51, 1.525, 0.0), stamp=1.0)
    layered.update_map(0.51, 1.525, 0.0)
    row = layer.costmap[30]
    assert row[30] == LETHAL_OBSTACLE  # x = 1.51 m
    assert (row[11:30] == FREE_SPACE).all()  # ray-traced free up to the endpoint
    assert row[31] == NO_INFORMATION  # nothing seen beyond it
    # the obstacle has gone: the next beam reaches 2 m and clears the old mark
    layer.add_scan('scan', [2.0], 0.0, 0.01, 0.1, 10.0, (0.51, 1.525, 0.0), stamp=2.0)
    layered.update_map(0.51, 1.525, 0.0)
    assert layer.costmap[30, 30] == FREE_SPACE
    assert layer.costmap[30, 50] == LETHAL_OBSTACLE
    assert layered.costmap.costmap[30, 50] == LETHAL_OBSTACLE


def test_ranges_limit_marking_and_clearing():
    layered = _layered()
    layer = _scan_layer(layered, obstacle_max_range=1.0, raytrace_max_range=0.5)
    layer.add_scan('scan', [0.8, 1.5], 0.0, math.pi / 2, 0.1, 10.0, (0.5, 0.525, 0.0))
    layered.update_map(0.5, 0.525, 0.0)
    assert layer.costmap[10, 26] == LETHAL_OBSTACLE  # 0.8 m ahead: marked
    assert layer.costmap[40, 10] == NO_INFORMATION  # 1.5 m to the left: past obstacle_max_range
    assert layer.costmap[10, 19] == FREE_SPACE  # cleared within raytrace_max_range (10 cells)
    assert layer.costmap[10, 21] == NO_INFORMATION  # ...and not beyond it


def test_obstacle_layer_refuses_bad_parameters_in_one_line():
    layered = _layered()
    with pytest.raises(ParameterError, match=r'^obstacle_layer\.scan\.obstacle_max_range: '
                       r'expected float, got .yes.$'):
        _scan_layer(layered, obstacle_max_range='yes')
    with pytest.raises(ParameterError, match='data_type'):
        _scan_layer(layered, data_type='Image')


def _bresenham(x0: int, y0: int, x1: int, y1: int, max_length: int) -> list[tuple[int, int]]:
    """Upstream's raytraceLine/bresenham2D, a cell at a time, for comparison."""
    dx, dy = x1 - x0, y1 - y0
    dist = math.hypot(dx, dy)
    scale = 1.0 if dist == 0 else min(1.0, max_length / dist)
    sx, sy = (dx > 0) - (dx < 0), (dy > 0) - (dy < 0)
    x_major = abs(dx) >= abs(dy)
    da, db = (abs(dx), abs(dy)) if x_major else (abs(dy), abs(dx))
    error, x, y, cells = da // 2, x0, y0, []
    for _ in range(min(int(scale * da), da)):
        cells.append((x, y))
        if x_major:
            x += sx
        else:
            y += sy
        error += db
        if error >= da:
            error -= da
            if x_major:
                y += sy
            else:
                x += sx
    return cells


def test_vectorised_raytrace_matches_bresenham():
    rng = np.random.default_rng(3)
    x1, y1 = rng.integers(0, 80, size=200), rng.integers(0, 80, size=200)
    xs, ys = raytrace_cells(40, 35, x1, y1, max_length=30)
    expected = [cell for a, b in zip(x1.tolist(), y1.tolist(), strict=True)
                for cell in _bresenham(40, 35, a, b, 30)]
    assert list(zip(xs.tolist(), ys.tolist(), strict=True)) == expected


def test_rolling_window_keeps_what_stays_in_view():
    layered = _layered(rolling=True)
    layer = _scan_layer(layered)
    layer.add_points('scan', np.array([[1.2, 1.5]]), (1.0, 1.5))
    layered.update_map(1.5, 1.5, 0.0)
    origin = layered.costmap.origin_x
    assert layered.costmap.world_to_map(1.2, 1.5) is not None
    layer.sources['scan'].observations.clear()
    layered.update_map(2.0, 1.5, 0.0)  # half a metre on: the window moves 10 cells
    assert layered.costmap.origin_x == pytest.approx(origin + 0.5)
    cell = layered.costmap.world_to_map(1.2, 1.5)
    assert cell is not None and layered.costmap.costmap[cell[1], cell[0]] == LETHAL_OBSTACLE


def test_clear_services_reset_obstacles_only():
    layered = _layered()
    static = StaticLayer('static_layer', layered, {}, {'track_unknown_space': True})
    layered.plugins.insert(0, static)
    layer = _scan_layer(layered)
    grid = np.zeros((60, 60), dtype=np.int8)
    grid[5, 5] = 100
    static.process_map(60, 60, 0.05, 0.0, 0.0, grid.ravel())
    layer.costmap[:] = FREE_SPACE
    layer.costmap[30, 32] = layer.costmap[30, 55] = LETHAL_OBSTACLE
    clear_region(layered, 1.5, 1.5, 1.0, invert=False)  # clear_around: the 1 m square
    assert layer.costmap[30, 32] == NO_INFORMATION and layer.costmap[30, 55] == LETHAL_OBSTACLE
    clear_region(layered, 1.5, 1.5, 1.0, invert=True)  # clear_except: all but the square
    assert layer.costmap[30, 55] == NO_INFORMATION
    layer.costmap[30, 40] = LETHAL_OBSTACLE
    clear_entirely(layered)
    assert (layer.costmap == NO_INFORMATION).all()
    layered.update_map(1.5, 1.5, 0.0)
    assert layered.costmap.costmap[5, 5] == LETHAL_OBSTACLE  # the static map stays


LOCAL_COSTMAP = {  # the shape of nav2_bringup's local_costmap ros__parameters
    'update_frequency': 5.0, 'publish_frequency': 2.0, 'global_frame': 'odom',
    'robot_base_frame': 'base_link', 'rolling_window': True, 'width': 3, 'height': 3,
    'resolution': 0.05, 'robot_radius': 0.22, 'plugins': ['voxel_layer', 'inflation_layer'],
    'inflation_layer': {'plugin': 'nav2_costmap_2d::InflationLayer',
                        'cost_scaling_factor': 3.0, 'inflation_radius': 0.55},
    'voxel_layer': {'plugin': 'nav2_costmap_2d::VoxelLayer', 'enabled': True,
                    'publish_voxel_map': True, 'origin_z': 0.0, 'z_resolution': 0.05,
                    'z_voxels': 16, 'max_obstacle_height': 2.0, 'mark_threshold': 0,
                    'observation_sources': 'scan',
                    'scan': {'topic': '/scan', 'max_obstacle_height': 2.0, 'clearing': True,
                             'marking': True, 'data_type': 'LaserScan',
                             'raytrace_max_range': 3.0, 'raytrace_min_range': 0.0,
                             'obstacle_max_range': 2.5, 'obstacle_min_range': 0.0}},
    'always_send_full_costmap': True,
}


def test_a_nav2_params_file_builds_its_costmap_unchanged():
    config = build_costmap(LOCAL_COSTMAP, 'local_costmap')
    layered = config.layered
    assert (layered.costmap.size_x, layered.costmap.size_y) == (60, 60)
    assert layered.is_rolling() and layered.global_frame == 'odom'
    assert [type(layer).__name__ for layer in layered.plugins] == ['ObstacleLayer',
                                                                   'InflationLayer']
    assert config.layer('voxel_layer').sources['scan'].clearing is True
    assert layered.inscribed_radius == pytest.approx(0.22 * math.cos(math.pi / 16), abs=0.011)
    assert config.messages == []
    # a scan seen by the voxel layer ends up inflated in the master grid
    voxel = config.layer('voxel_layer')
    voxel.add_scan('scan', [1.0], 0.0, 0.1, 0.1, 10.0, (0.0, 0.0, 0.0))
    layered.update_map(0.0, 0.0, 0.0)
    cell = layered.costmap.world_to_map(1.0, 0.0)
    assert layered.costmap.costmap[cell[1], cell[0]] == LETHAL_OBSTACLE
    assert layered.costmap.costmap[cell[1], cell[0] - 3] == INSCRIBED_INFLATED_OBSTACLE


def test_defaults_flattened_names_and_refusals():
    config = build_costmap({})
    assert list(config.plugin_types) == ['static_layer', 'obstacle_layer', 'inflation_layer']
    assert config.layered.costmap.size_x == 50  # 5 m at 0.1 m
    flat = build_costmap({'plugins': ['obstacle_layer'], 'obstacle_layer.observation_sources':
                          'scan', 'obstacle_layer.scan.obstacle_max_range': 4.0,
                          'footprint': '[[1, 2]]'})
    assert flat.layer('obstacle_layer').sources['scan'].obstacle_max_range == 4.0
    assert flat.used_radius and flat.messages[-1] == (
        'The footprint parameter is invalid: "[[1, 2]]", using radius (0.100000) instead')
    with pytest.raises(ParameterError, match=r'^costmap\.width: expected int, got 3\.5$'):
        build_costmap({'width': 3.5})
    with pytest.raises(ParameterError, match='Failed to create plugin keepout of type '
                       'nav2_costmap_2d::KeepoutFilter'):
        build_costmap({'plugins': ['keepout'],
                       'keepout': {'plugin': 'nav2_costmap_2d::KeepoutFilter'}})


def test_messages_round_trip_as_the_publisher_and_static_layer():
    from nav2_costmap_2d.messages import occupancy_grid, take_map
    from nav_msgs.msg import OccupancyGrid
    layered = _layered()
    static = StaticLayer('static_layer', layered, {}, {'track_unknown_space': True})
    layered.add_plugin(static)
    incoming = OccupancyGrid()
    incoming.info.width, incoming.info.height, incoming.info.resolution = 4, 3, 0.5
    incoming.info.origin.position.x = -1.0
    incoming.data = [0, 100, -1, 0] * 3
    take_map(static, incoming)
    layered.update_map(0.0, 0.5, 0.0)
    assert layered.costmap.costmap[0].tolist() == [0, LETHAL_OBSTACLE, NO_INFORMATION, 0]
    out = occupancy_grid(layered.costmap, 'map', map_vis_z=0.1)
    assert (out.info.width, out.info.height, out.info.resolution) == (4, 3, 0.5)
    assert (out.info.origin.position.x, out.info.origin.position.z) == (-1.0, 0.1)
    assert list(out.data) == [0, 100, -1, 0] * 3 and out.header.frame_id == 'map'


def test_inf_is_valid_clears_without_marking():
    layered = _layered()
    layer = _scan_layer(layered, inf_is_valid=True, raytrace_max_range=3.0)
    layer.costmap[10, 30] = LETHAL_OBSTACLE  # an old mark 1 m ahead
    layer.add_scan('scan', [math.inf], 0.0, 0.1, 0.1, 10.0, (0.51, 0.525, 0.0))
    layered.update_map(0.51, 0.525, 0.0)
    assert layer.costmap[10, 30] == FREE_SPACE  # the infinite reading cleared it
    # ...and marked nothing: it stands at range_max, beyond obstacle_max_range (2.5 m)
    assert (layer.costmap != LETHAL_OBSTACLE).all()


def test_observation_persistence_keeps_recent_scans():
    layered = _layered()
    layer = _scan_layer(layered, observation_persistence=1.0, clearing=False)
    layer.add_scan('scan', [1.0], 0.0, 0.1, 0.1, 10.0, (0.51, 0.525, 0.0), stamp=10.0)
    layer.add_scan('scan', [1.0], math.pi / 2, 0.1, 0.1, 10.0, (0.51, 0.525, 0.0), stamp=10.5)
    assert len(layer.sources['scan'].observations) == 2
    layer.add_scan('scan', [1.0], math.pi, 0.1, 0.1, 10.0, (2.0, 0.525, 0.0), stamp=11.2)
    assert [stamp for stamp, _ in layer.sources['scan'].observations] == [10.5, 11.2]


def test_combination_methods_and_an_unknown_one():
    layered = _layered()
    layer = ObstacleLayer('obstacle_layer', layered, {'combination_method': 0},
                          {'track_unknown_space': True})
    layer.costmap[:] = NO_INFORMATION
    layer.costmap[0, 0], layer.costmap[0, 1] = 10, FREE_SPACE
    layered.costmap.costmap[:] = 200
    layer.update_costs(layered.costmap)  # Overwrite: known cells replace the master's
    assert layered.costmap.costmap[0, :3].tolist() == [10, 0, 200]
    odd = ObstacleLayer('obstacle_layer', layered, {'combination_method': 7})
    assert odd.combination_method == 1 and 'Param combination_method: 7' in odd.warnings[0]


def test_inflate_around_unknown():
    layered = _layered(track_unknown=True)
    static = StaticLayer('static_layer', layered, {}, {'track_unknown_space': True})
    layered.add_plugin(static)
    layered.add_plugin(InflationLayer('inflation_layer', layered,
                                      {'inflation_radius': 0.3, 'cost_scaling_factor': 3.0,
                                       'inflate_around_unknown': True}))
    layered.set_footprint(make_footprint_from_string(SQUARE))
    grid = np.zeros((60, 60), dtype=np.int8)
    grid[30, 30] = -1
    static.process_map(60, 60, 0.05, 0.0, 0.0, grid.ravel())
    layered.update_map(0.5, 0.5, 0.0)
    # the unknown cell is a source: distance 0 makes it lethal, as upstream's rule gives
    assert layered.costmap.costmap[30, 30] == LETHAL_OBSTACLE
    assert layered.costmap.costmap[30, 33] == INSCRIBED_INFLATED_OBSTACLE
    assert layered.costmap.costmap[30, 36] == int(252 * math.exp(-3.0 * (0.3 - 0.2)))


def test_static_layer_in_a_rolling_window_follows_the_robot():
    layered = _layered(rolling=True)
    static = StaticLayer('static_layer', layered, {}, {'track_unknown_space': True})
    layered.add_plugin(static)
    grid = np.zeros((200, 200), dtype=np.int8)
    grid[100, 150] = 100  # (7.5, 5.0) in a 10 m map
    static.process_map(200, 200, 0.05, 0.0, 0.0, grid.ravel())
    assert layered.costmap.size_x == 60  # the rolling window keeps its own size
    layered.update_map(7.0, 5.0, 0.0)
    cell = layered.costmap.world_to_map(7.51, 5.01)
    assert layered.costmap.costmap[cell[1], cell[0]] == LETHAL_OBSTACLE
    assert (layered.costmap.costmap == LETHAL_OBSTACLE).sum() == 1
