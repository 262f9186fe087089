"""Nav2's map files: a YAML of metadata next to a PGM/PNG/BMP image, to and from OccupancyGrid.

The rules are upstream's map_io: a pixel's grey level p (0-255, colour images by luma, a
transparent pixel unknown in trinary and scale modes) becomes occupancy
`(255 - p) / 255` (`p / 255` with negate), >= occupied_thresh is 100, <= free_thresh is 0,
in between is -1 (trinary) or scaled to 1-99 (scale); raw mode takes p itself (0-100, else
-1). The image's top row is the grid's last. Saving writes trinary as 0/254/205 with the
fixed thresholds 0.65/0.196, scale as grey levels (unknown transparent), raw as the values.
Log lines go to the `map_io` logger with upstream's texts.
"""

from __future__ import annotations

import enum
import math
import os
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import yaml
from nav_msgs.msg import OccupancyGrid
from PIL import Image, UnidentifiedImageError
from rclpy.logging import get_logger

OCC_GRID_UNKNOWN = -1
OCC_GRID_FREE = 0
OCC_GRID_OCCUPIED = 100
WRITABLE_FORMATS = ('bmp', 'pgm', 'png')  # upstream's "blessed" formats
PIL_FORMATS = {'bmp': 'BMP', 'pgm': 'PPM', 'png': 'PNG'}


class MapMode(enum.Enum):
    TRINARY = 'trinary'
    SCALE = 'scale'
    RAW = 'raw'


def map_mode_from_string(name: str) -> MapMode:
    try:
        return MapMode(name.lower())
    except ValueError:
        raise ValueError(f"mode '{name}' is not one of trinary, scale, raw") from None


class LoadMapStatus(enum.Enum):
    LOAD_MAP_SUCCESS = 0
    MAP_DOES_NOT_EXIST = 1
    INVALID_MAP_METADATA = 2
    INVALID_MAP_DATA = 3


class MapYamlError(ValueError):
    """A map YAML that cannot be used; the text names the file position and the tag."""


@dataclass
class LoadParameters:
    image_file_name: str = ''
    resolution: float = 0.0
    origin: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    free_thresh: float = 0.0
    occupied_thresh: float = 0.0
    mode: MapMode = MapMode.TRINARY
    negate: int = 0


@dataclass
class SaveParameters:
    map_file_name: str = ''
    image_format: str = ''
    free_thresh: float = 0.0
    occupied_thresh: float = 0.0
    mode: MapMode = MapMode.TRINARY


def _log():
    return get_logger('map_io')


def fmt(value: float) -> str:
    """A number as C++'s ostream prints it (six significant digits)."""
    return f'{value:g}'


def expand_user_home_dir_if_needed(yaml_filename: str) -> str:
    if not yaml_filename.startswith('~/'):
        return yaml_filename
    home = os.environ.get('HOME', '')
    if not home:
        _log().info("Map yaml file name starts with '~/' but no HOME variable set. \n"
                    '[INFO] [map_io] User home dir will be not expanded \n')
        return yaml_filename
    return home + yaml_filename[1:]


def _tag(doc: dict, key: str, kind: type, words: str):
    if key not in doc:
        raise MapYamlError(f"Failed to parse YAML tag '{key}' for reason: key not found")
    value = doc[key]
    if kind is float and isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(value)
    if kind is str and isinstance(value, (str, int, float)) and not isinstance(value, bool):
        return str(value)
    raise MapYamlError(
        f"Failed to parse YAML tag '{key}' for reason: bad conversion ({words} expected, "
        f'got {value!r})')


def load_map_yaml(yaml_filename: str) -> LoadParameters:
    """Read a map YAML; raises MapYamlError (or OSError) with the reason."""
    path = expand_user_home_dir_if_needed(yaml_filename)
    try:
        with open(path, encoding='utf-8') as stream:
            doc = yaml.safe_load(stream)
    except OSError:
        raise MapYamlError(f'bad file: {yaml_filename}') from None
    except yaml.YAMLError as error:
        raise MapYamlError(str(error).replace('\n', ' ')) from None
    if not isinstance(doc, dict):
        raise MapYamlError('the file is not a YAML map of tags (image, resolution, origin, '
                           'negate, occupied_thresh, free_thresh, mode)')
    params = LoadParameters()
    image = _tag(doc, 'image', str, 'a file name')
    if not image:
        raise MapYamlError('The image tag was empty.')
    if not image.startswith('/'):
        image = os.path.join(os.path.dirname(yaml_filename) or '.', image)
    params.image_file_name = image
    params.resolution = _tag(doc, 'resolution', float, 'a number')
    origin = doc.get('origin')
    if (not isinstance(origin, list) or not all(
            isinstance(v, (int, float)) and not isinstance(v, bool) for v in origin)):
        if 'origin' not in doc:
            raise MapYamlError("Failed to parse YAML tag 'origin' for reason: key not found")
        raise MapYamlError("Failed to parse YAML tag 'origin' for reason: bad conversion "
                           f'(a list [x, y, yaw] expected, got {origin!r})')
    if len(origin) != 3:
        raise MapYamlError(
            f"value of the 'origin' tag should have 3 elements, not {len(origin)}")
    params.origin = [float(v) for v in origin]
    params.free_thresh = _tag(doc, 'free_thresh', float, 'a number')
    params.occupied_thresh = _tag(doc, 'occupied_thresh', float, 'a number')
    if 'mode' in doc:
        params.mode = map_mode_from_string(str(doc['mode']))
    negate = doc.get('negate')
    if isinstance(negate, bool) or (isinstance(negate, int)):
        params.negate = int(negate)
    elif 'negate' not in doc:
        raise MapYamlError("Failed to parse YAML tag 'negate' for reason: key not found")
    else:
        raise MapYamlError("Failed to parse YAML tag 'negate' for reason: bad conversion "
                           f'(0, 1, true or false expected, got {negate!r})')
    log = _log()
    log.info(f'resolution: {fmt(params.resolution)}')
    for index in range(3):
        log.info(f'origin[{index}]: {fmt(params.origin[index])}')
    log.info(f'free_thresh: {fmt(params.free_thresh)}')
    log.info(f'occupied_thresh: {fmt(params.occupied_thresh)}')
    log.info(f'mode: {params.mode.value}')
    log.info(f'negate: {params.negate}')
    return params


def _grey_and_alpha(image: Image.Image) -> tuple[np.ndarray, np.ndarray | None]:
    """8-bit grey levels (luma for colour) and the alpha channel if the image has one."""
    if image.mode in ('I;16', 'I;16B', 'I;16L', 'I'):
        grey = np.rint(np.asarray(image, dtype=np.float64) / 257.0).clip(0, 255)
        return grey.astype(np.uint8), None
    has_alpha = image.mode in ('LA', 'RGBA', 'PA') or 'transparency' in image.info
    if image.mode == 'P' or (has_alpha and image.mode not in ('LA', 'RGBA')):
        image = image.convert('RGBA' if has_alpha else 'RGB')
    alpha = np.asarray(image.getchannel('A')) if has_alpha else None
    grey = np.asarray(image if image.mode == 'L' else image.convert('L'))
    return grey, alpha


def occupancy_from_grey(grey: np.ndarray, alpha: np.ndarray | None,
                        params: LoadParameters) -> np.ndarray:
    """The image's occupancy values (int8, image row order) by upstream's rules."""
    if params.mode == MapMode.RAW:
        values = grey.astype(np.int16)
        return np.where(values > OCC_GRID_OCCUPIED, OCC_GRID_UNKNOWN, values).astype(np.int8)
    # float32 as upstream's Eigen arrays: a pixel on a threshold falls the same side
    occupancy = grey.astype(np.float32) / np.float32(255.0)
    if not params.negate:
        occupancy = np.float32(1.0) - occupancy
    free_t, occupied_t = np.float32(params.free_thresh), np.float32(params.occupied_thresh)
    result = np.full(grey.shape, OCC_GRID_UNKNOWN, dtype=np.int8)
    result[occupancy >= occupied_t] = OCC_GRID_OCCUPIED
    result[occupancy <= free_t] = OCC_GRID_FREE
    if params.mode == MapMode.SCALE:
        between = (occupancy > free_t) & (occupancy < occupied_t)
        scaled = (occupancy - free_t) / (occupied_t - free_t) * np.float32(100.0)
        # std::round: halves away from zero (the values are positive)
        result[between] = np.floor(scaled[between] + np.float32(0.5)).astype(np.int8)
    if alpha is not None:
        result[alpha < 255] = OCC_GRID_UNKNOWN
    return result


def yaw_quaternion(yaw: float) -> tuple[float, float, float, float]:
    return 0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0)


def load_map_from_file(params: LoadParameters, clock_now) -> OccupancyGrid:
    """The grid of params' image; raises OSError or ValueError with the reason."""
    _log().info(f'Loading image_file: {params.image_file_name}')
    try:
        with Image.open(params.image_file_name) as image:
            image.load()
            grey, alpha = _grey_and_alpha(image)
    except FileNotFoundError:
        raise OSError(f'unable to open file {params.image_file_name}: '
                      'No such file or directory') from None
    except UnidentifiedImageError:
        raise ValueError('not an image Pillow can read (PGM, PNG, BMP, ...)') from None
    height, width = grey.shape
    grid = OccupancyGrid()
    grid.info.width, grid.info.height = width, height
    grid.info.resolution = params.resolution
    grid.info.origin.position.x, grid.info.origin.position.y = params.origin[:2]
    orientation = grid.info.origin.orientation
    orientation.x, orientation.y, orientation.z, orientation.w = \
        yaw_quaternion(params.origin[2])
    # The image's first row is the top of the map; the grid starts at its bottom.
    cells = occupancy_from_grey(grey, alpha, params)[::-1]
    grid.data = cells.tobytes()
    stamp = clock_now().to_msg()
    grid.info.map_load_time = stamp
    grid.header.stamp = stamp
    grid.header.frame_id = 'map'
    _log().info(f'Read map {params.image_file_name}: {width} X {height} map @ '
                f'{fmt(grid.info.resolution)} m/cell')
    return grid


def load_map_from_yaml(yaml_file: str, clock_now) -> tuple[LoadMapStatus, OccupancyGrid | None]:
    """(status, grid): one error line on the `map_io` logger when it fails."""
    log = _log()
    if not yaml_file:
        log.error("YAML file name is empty, can't load!")
        return LoadMapStatus.MAP_DOES_NOT_EXIST, None
    log.info(f'Loading yaml file: {yaml_file}')
    try:
        params = load_map_yaml(yaml_file)
    except MapYamlError as error:
        log.error(f'Failed processing YAML file {yaml_file} for reason: {error}')
        return LoadMapStatus.INVALID_MAP_METADATA, None
    except ValueError as error:
        log.error(f'Failed to parse map YAML loaded from file {yaml_file} for reason: {error}')
        return LoadMapStatus.INVALID_MAP_METADATA, None
    try:
        return LoadMapStatus.LOAD_MAP_SUCCESS, load_map_from_file(params, clock_now)
    except (OSError, ValueError) as error:
        log.error(f'Failed to load image file {params.image_file_name} for reason: {error}')
        return LoadMapStatus.INVALID_MAP_DATA, None


def validate_save_parameters(save: SaveParameters) -> None:
    """Raise ValueError naming what is wrong with the thresholds or the format (0 and ''
    mean "the default", as upstream)."""
    if save.occupied_thresh > 1.0:
        raise ValueError('Threshold_occupied must be 1.0 or less')
    if save.free_thresh < 0.0:
        raise ValueError('Free threshold must be 0.0 or greater')
    if 0.0 not in (save.free_thresh, save.occupied_thresh) \
            and save.occupied_thresh <= save.free_thresh:
        raise ValueError('Threshold_free must be smaller than threshold_occupied')
    if save.image_format and save.image_format.lower() not in WRITABLE_FORMATS:
        raise ValueError(f"image format '{save.image_format}' is not one of "
                         f"{', '.join(WRITABLE_FORMATS)}")


def check_save_parameters(save: SaveParameters) -> SaveParameters:
    """Upstream's defaults and checks; raises ValueError naming the bad value."""
    log = _log()
    if not save.map_file_name:
        save.map_file_name = f'map_{int(time.time())}'
        log.warning(f'Map file unspecified. Map will be saved to {save.map_file_name} file')
    if save.occupied_thresh == 0.0:
        save.occupied_thresh = 0.65
        log.warning('Occupied threshold unspecified. Setting it to default value: '
                    f'{fmt(save.occupied_thresh)}')
    if save.free_thresh == 0.0:
        save.free_thresh = 0.25
        log.warning('Free threshold unspecified. Setting it to default value: '
                    f'{fmt(save.free_thresh)}')
    validate_save_parameters(save)
    if not save.image_format:
        save.image_format = 'png' if save.mode == MapMode.SCALE else 'pgm'
        log.warning(f'Image format unspecified. Setting it to: {save.image_format}')
    save.image_format = save.image_format.lower()
    if save.mode == MapMode.SCALE and save.image_format == 'pgm':
        log.warning(f"Map mode 'scale' requires transparency, but format "
                    f"'{save.image_format}' does not support it. Consider switching image "
                    "format to 'png'.")
    return save


def image_from_grid(grid: OccupancyGrid, save: SaveParameters) -> Image.Image:
    width, height = grid.info.width, grid.info.height
    cells = np.frombuffer(bytes(grid.data), dtype=np.int8).reshape(height, width)[::-1]
    cells = cells.astype(np.int16)
    unknown = (cells < 0) | (cells > 100)
    if save.mode == MapMode.TRINARY:
        free_int = round(save.free_thresh * 100.0)
        occupied_int = round(save.occupied_thresh * 100.0)
        grey = np.full(cells.shape, 205, dtype=np.uint8)
        grey[~unknown & (cells <= free_int)] = 254
        grey[~unknown & (cells >= occupied_int) & (cells > free_int)] = 0
        return Image.fromarray(grey, 'L')
    if save.mode == MapMode.SCALE:
        grey = np.where(unknown, 128, np.rint((100.0 - cells) * 255.0 / 100.0)).astype(np.uint8)
        if save.image_format == 'pgm':  # no alpha channel there
            return Image.fromarray(grey, 'L')
        alpha = np.where(unknown, 0, 255).astype(np.uint8)
        return Image.fromarray(np.dstack([grey, grey, grey, alpha]), 'RGBA')
    grey = np.where(unknown, 255, cells).astype(np.uint8)
    return Image.fromarray(grey, 'L')


def _yaw(grid: OccupancyGrid) -> float:
    q = grid.info.origin.orientation
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def metadata_text(grid: OccupancyGrid, save: SaveParameters, image_name: str) -> str:
    """The YAML as upstream's emitter writes it (3 decimals, yaw with 7 digits)."""
    origin = grid.info.origin.position
    lines = [f'image: {image_name}', f'mode: {save.mode.value}',
             f'resolution: {grid.info.resolution:.3f}',
             f'origin: [{origin.x:.3f}, {origin.y:.3f}, {_yaw(grid):.7g}]', 'negate: 0']
    if save.mode == MapMode.TRINARY:
        # the saved pixels are 0/254/205 whatever the thresholds: these separate them
        lines += ['occupied_thresh: 0.65', 'free_thresh: 0.196']
    else:
        lines += [f'occupied_thresh: {save.occupied_thresh:.3f}',
                  f'free_thresh: {save.free_thresh:.3f}']
    return '\n'.join(lines)


def save_map_to_file(grid: OccupancyGrid, save: SaveParameters) -> bool:
    """Write the image and its YAML; False (one error line) when it cannot."""
    log = _log()
    try:
        save = check_save_parameters(SaveParameters(**vars(save)))
        if len(grid.data) != grid.info.width * grid.info.height:
            raise ValueError(f'the map has {len(grid.data)} cells, not width x height = '
                             f'{grid.info.width * grid.info.height}')
        log.info(f'Received a {grid.info.width} X {grid.info.height} map @ '
                 f'{fmt(grid.info.resolution)} m/pix')
        image_file = f'{save.map_file_name}.{save.image_format}'
        image = image_from_grid(grid, save)
        log.info(f'Writing map occupancy data to {image_file}')
        image.save(image_file, format=PIL_FORMATS[save.image_format])
        yaml_file = f'{save.map_file_name}.yaml'
        log.info(f'Writing map metadata to {yaml_file}')
        Path(yaml_file).write_text(metadata_text(grid, save, Path(image_file).name))
    except (OSError, ValueError) as error:
        log.error(f'Failed to write map for reason: {error}')
        return False
    log.info('Map saved')
    return True
