"""nav2_map_server end to end: a map file made here -> map_server -> /map, map_saver_cli and
map_saver/save_map write it back, map_server/load_map refuses bad files without touching /map.

One map_server and one map_saver_server for the module, brought up by a lifecycle_manager
with autostart, as Nav2's bringup does.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from nav2_msgs.srv import LoadMap, SaveMap
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetMap
from PIL import Image
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from ws_testing import TestNode, executable

# A 5 x 3 image, top row first: grey levels on both sides of Nav2's default thresholds.
PIXELS = [[0, 254, 205, 100, 255],
          [128, 10, 60, 200, 51],
          [255, 255, 0, 0, 205]]
# occupancy = (255 - p) / 255: >= 0.65 occupied (100), <= 0.196 free (0), else unknown (-1)
# (205 gives 0.19608: unknown); the grid starts at the image's bottom row.
TRINARY_CELLS = [0, 0, 100, 100, -1,
                 -1, 100, 100, -1, 100,
                 100, 0, -1, -1, 0]
# scale mode: in between -> round((occupancy - 0.196) / (0.65 - 0.196) * 100)
SCALE_CELLS = [0, 0, 100, 100, 0,
               67, 100, 100, 4, 100,
               100, 0, 0, 91, 0]
MAP_YAML = ('image: {image}\nresolution: 0.05\norigin: [-1.5, 2.25, 0.0]\nnegate: 0\n'
            'occupied_thresh: 0.65\nfree_thresh: 0.196\n{extra}')
LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     reliability=ReliabilityPolicy.RELIABLE)


def write_map(folder: Path, name: str, image: str = 'world.pgm', extra: str = '') -> Path:
    path = folder / f'{name}.yaml'
    path.write_text(MAP_YAML.format(image=image, extra=extra))
    return path


@pytest.fixture(scope='module')
def maps(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp('maps')
    Image.fromarray(np.array(PIXELS, dtype=np.uint8), 'L').save(folder / 'world.pgm')
    write_map(folder, 'world')
    write_map(folder, 'world_scale', extra='mode: scale\n')
    write_map(folder, 'no_image', image='missing.pgm')
    # a typo'd key next to the real one: warned about, the real one still used
    (folder / 'params.yaml').write_text(
        f'map_server:\n  ros__parameters:\n    yaml_filename: {folder / "world.yaml"}\n'
        '    yaml_file_name: typo.yaml\n')
    return folder


@pytest.fixture(scope='module')
def stack(module_launch, module_ros_env, maps):
    map_server = module_launch('nav2_map_server', 'map_server', '--ros-args',
                               '--params-file', str(maps / 'params.yaml'))
    saver = module_launch('nav2_map_server', 'map_saver_server')
    manager = module_launch('nav2_lifecycle_manager', 'lifecycle_manager', '--ros-args',
                            '-p', "node_names:=['map_server', 'map_saver']",
                            '-p', 'autostart:=true')
    manager.wait_for_output('Managed nodes are active', timeout=30)
    probe = TestNode(int(module_ros_env['ROS_DOMAIN_ID']))
    yield {'map_server': map_server, 'saver': saver, 'manager': manager, 'probe': probe,
           'env': module_ros_env}
    probe.close()


def cells(grid: OccupancyGrid) -> list[int]:
    return list(np.frombuffer(bytes(grid.data), dtype=np.int8))


def latched_map(probe: TestNode) -> OccupancyGrid:
    received = probe.collect(OccupancyGrid, '/map', LATCHED)
    probe.spin_until(lambda: received, 10, 'the latched /map')
    return received[-1]


def new_lines(output: str, since: int, level: str) -> list[str]:
    return [line for line in output[since:].splitlines() if line.startswith(f'[{level}]')]


def test_map_topic_holds_the_cells_nav2s_rules_give(stack, maps):
    stack['map_server'].wait_for_output(
        rf'\[map_io\]: Read map {re.escape(str(maps))}/world.pgm: 5 X 3 map @ 0.05 m/cell')
    grid = latched_map(stack['probe'])
    assert (grid.info.width, grid.info.height) == (5, 3)
    assert grid.info.resolution == pytest.approx(0.05)
    origin = grid.info.origin
    assert (origin.position.x, origin.position.y, origin.orientation.w) == (-1.5, 2.25, 1.0)
    assert grid.header.frame_id == 'map'
    assert cells(grid) == TRINARY_CELLS
    served = stack['probe'].call(GetMap, '/map_server/map', GetMap.Request()).map
    assert cells(served) == TRINARY_CELLS
    # the params file's unknown key: one warning naming it, nothing else changed
    warnings = new_lines(stack['map_server'].output, 0, 'WARN')
    assert len(warnings) == 1 and "'yaml_file_name'" in warnings[0], warnings


def test_map_saver_cli_writes_nav2s_format_and_it_loads_back_identical(stack, maps, launch,
                                                                       tmp_path):
    before = cells(latched_map(stack['probe']))
    cli = launch(argv=[executable('nav2_map_server', 'map_saver_cli'), '-f',
                       str(tmp_path / 'saved')], env=stack['env'])
    assert cli.wait(timeout=30) == 0, cli.output
    for line in (rf"\[map_saver\]: Saving map from 'map' topic to '{tmp_path}/saved' file",
                 r'\[map_io\]: Received a 5 X 3 map @ 0.05 m/pix',
                 rf'\[map_io\]: Writing map occupancy data to {tmp_path}/saved.pgm',
                 r'\[map_saver\]: Map saved successfully'):
        assert re.search(line, cli.output), cli.output
    assert (tmp_path / 'saved.yaml').read_text() == (
        'image: saved.pgm\nmode: trinary\nresolution: 0.050\norigin: [-1.500, 2.250, 0]\n'
        'negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196')
    # trinary pixels: occupied 0, free 254, unknown 205, top row first
    saved = np.asarray(Image.open(tmp_path / 'saved.pgm'))
    grey = {100: 0, 0: 254, -1: 205}
    assert saved[::-1].ravel().tolist() == [grey[c] for c in before]
    response = stack['probe'].call(LoadMap, '/map_server/load_map',
                                   LoadMap.Request(map_url=str(tmp_path / 'saved.yaml')))
    assert response.result == LoadMap.Response.RESULT_SUCCESS
    assert cells(response.map) == before == TRINARY_CELLS
    assert cells(latched_map(stack['probe'])) == TRINARY_CELLS


def test_load_map_scale_mode_and_save_map_service_raw(stack, maps, tmp_path):
    probe = stack['probe']
    response = probe.call(LoadMap, '/map_server/load_map',
                          LoadMap.Request(map_url=str(maps / 'world_scale.yaml')))
    assert response.result == LoadMap.Response.RESULT_SUCCESS
    assert cells(response.map) == SCALE_CELLS
    request = SaveMap.Request(map_topic='map', map_url=str(tmp_path / 'raw'),
                              image_format='png', map_mode='raw')
    assert probe.call(SaveMap, '/map_saver/save_map', request, timeout=15).result
    # raw: the cell values themselves, unknown 255
    saved = np.asarray(Image.open(tmp_path / 'raw.png'))
    assert saved[::-1].ravel().tolist() == [255 if c < 0 else c for c in SCALE_CELLS]
    assert 'mode: raw\n' in (tmp_path / 'raw.yaml').read_text()
    probe.call(LoadMap, '/map_server/load_map',
               LoadMap.Request(map_url=str(maps / 'world.yaml')))  # back to the trinary map


@pytest.mark.parametrize('name, result, reason', [
    ('no_image.yaml', LoadMap.Response.RESULT_INVALID_MAP_DATA,
     r'Failed to load image file \S+/missing\.pgm for reason: .*No such file'),
    ('absent.yaml', LoadMap.Response.RESULT_INVALID_MAP_METADATA,
     r'Failed processing YAML file \S+/absent\.yaml for reason: bad file'),
])
def test_load_map_refusal_is_one_line_and_leaves_the_map(stack, maps, name, result, reason):
    probe, map_server = stack['probe'], stack['map_server']
    before = probe.call(GetMap, '/map_server/map', GetMap.Request()).map
    since = len(map_server.output)
    response = probe.call(LoadMap, '/map_server/load_map',
                          LoadMap.Request(map_url=str(maps / name)))
    assert response.result == result
    map_server.wait_for_output(reason)
    errors = new_lines(map_server.output, since, 'ERROR')
    assert len(errors) == 1 and re.search(reason, errors[0]), errors
    after = probe.call(GetMap, '/map_server/map', GetMap.Request()).map
    assert after.header.stamp == before.header.stamp
    assert cells(after) == cells(before) == cells(latched_map(probe))
