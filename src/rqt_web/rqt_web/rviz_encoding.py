"""The RViz page's binary data, made with numpy from a message (pure functions, no ROS).

Each encoder takes a message and returns (body, meta): the bytes the page draws and the
JSON it needs to draw them; ValueError names what in the message cannot be drawn.

- encode_cloud: sensor_msgs/PointCloud2 -> the finite points as float32 x, y, z, then, if
  coloured, uint8 r, g, b per point (rviz's RGB8 or Intensity colour transformer).
- encode_image: sensor_msgs/Image -> RGBA bytes (16-bit and float scaled min to max).
- encode_map: nav_msgs/OccupancyGrid -> RGBA bytes in rviz's "map", "costmap" or "raw" colour
  scheme.
"""

from __future__ import annotations

from typing import Any

# PointField datatypes (sensor_msgs/msg/PointField) as numpy type codes.
POINT_FIELD_TYPES = {1: 'i1', 2: 'u1', 3: 'i2', 4: 'u2', 5: 'i4', 6: 'u4', 7: 'f4', 8: 'f8'}


def _rainbow(value: Any) -> Any:
    """rviz's getRainbowColor (HSV hue 0 to 0.83) of values in [0, 1]: uint8 (n, 3)."""
    import numpy as np
    h = np.clip(value, 0.0, 1.0) * 5.0 + 1.0
    i = np.floor(h)
    f = h - i
    f = np.where(i % 2 == 0, 1.0 - f, f)
    n = 1.0 - f
    zero, one = np.zeros_like(h), np.ones_like(h)
    r = np.select([i <= 1, i == 2, i == 3, i == 4], [n, zero, zero, n], one)
    g = np.select([i <= 1, i == 2, i == 3, i == 4], [zero, n, one, one], n)
    b = np.select([i <= 1, i == 2, i == 3, i == 4], [one, one, n, zero], zero)
    return (np.stack([r, g, b], axis=1) * 255.0 + 0.5).astype(np.uint8)


def _packed(msg: Any) -> Any:
    """The message's points as a numpy byte array of width * height * point_step bytes."""
    import numpy as np
    data = np.frombuffer(msg.data, dtype=np.uint8)
    row = msg.width * msg.point_step
    if msg.height > 1 and msg.row_step > row:  # padded rows: drop the padding
        data = data[:msg.height * msg.row_step].reshape(msg.height, msg.row_step)[:, :row]
        data = np.ascontiguousarray(data).reshape(-1)
    if data.size < msg.height * row:
        raise ValueError(f'data holds {data.size} bytes, width * height * point_step is '
                         f'{msg.height * row}')
    return data[:msg.height * row]


def encode_cloud(msg: Any) -> tuple[bytes, dict]:
    """sensor_msgs/PointCloud2 -> float32 xyz of the finite points, then uint8 rgb if the
    cloud has colour, as rviz's default colour transformers give it: `rgb`/`rgba` packed in
    a float32 or uint32 (RGB8), else `intensity` on rviz's rainbow between its min and max."""
    import numpy as np
    fields = {f.name: f for f in msg.fields}
    for axis in 'xyz':
        if axis not in fields or fields[axis].datatype not in POINT_FIELD_TYPES:
            raise ValueError(f'no {axis} field of a numeric type')
    colour = next((name for name in ('rgb', 'rgba', 'intensity') if name in fields
                   and fields[name].datatype in POINT_FIELD_TYPES), None)
    order = '>' if msg.is_bigendian else '<'
    names = ['x', 'y', 'z'] + ([colour] if colour else [])
    formats = [order + POINT_FIELD_TYPES[fields[n].datatype] for n in names]
    if colour in ('rgb', 'rgba'):
        formats[3] = order + 'u4'  # the float32's bits are the packed 0x00RRGGBB
    count = msg.width * msg.height
    if msg.point_step <= 0 or count == 0:
        return b'', {'points': 0, 'color': None}
    try:
        points = np.ndarray((count,), buffer=_packed(msg), dtype=np.dtype(
            {'names': names, 'formats': formats, 'itemsize': msg.point_step,
             'offsets': [fields[n].offset for n in names]}))
    except (TypeError, ValueError) as error:
        raise ValueError(f'fields do not fit point_step {msg.point_step}: {error}') from None
    xyz = np.empty((count, 3), dtype='<f4')
    for i, axis in enumerate('xyz'):
        xyz[:, i] = points[axis]
    finite = np.isfinite(xyz).all(axis=1)
    xyz = xyz[finite]
    if colour in ('rgb', 'rgba'):
        packed = points[colour][finite]
        rgb = np.stack([(packed >> 16) & 255, (packed >> 8) & 255, packed & 255],
                       axis=1).astype(np.uint8)
    elif colour == 'intensity':
        values = points[colour][finite].astype(np.float64)
        valid = values[np.isfinite(values)]
        low, high = (float(valid.min()), float(valid.max())) if valid.size else (0.0, 0.0)
        span = high - low
        normalized = (values - low) / span if span > 0 else np.zeros_like(values)
        rgb = _rainbow(1.0 - normalized)
    else:
        rgb = None
    body = xyz.tobytes() + (rgb.tobytes() if rgb is not None else b'')
    return body, {'points': int(xyz.shape[0]), 'color': colour and ('intensity' if colour ==
                                                                    'intensity' else 'rgb')}


IMAGE_ENCODINGS = {  # encoding: (numpy type, channels)
    'rgb8': ('u1', 3), 'bgr8': ('u1', 3), 'rgba8': ('u1', 4), 'bgra8': ('u1', 4),
    'mono8': ('u1', 1), '8UC1': ('u1', 1), '8UC3': ('u1', 3), '8UC4': ('u1', 4),
    'mono16': ('u2', 1), '16UC1': ('u2', 1), '32FC1': ('f4', 1)}


def encode_image(msg: Any) -> tuple[bytes, dict]:
    """sensor_msgs/Image -> RGBA bytes for a canvas. 16-bit and float images are scaled from
    their min to max, as rviz's Image display does by default (Normalize Range)."""
    import numpy as np
    if msg.encoding not in IMAGE_ENCODINGS:
        raise ValueError(f'encoding {msg.encoding!r} is not drawn (drawn: '
                         f'{", ".join(IMAGE_ENCODINGS)})')
    kind, channels = IMAGE_ENCODINGS[msg.encoding]
    dtype = np.dtype(kind).newbyteorder('>' if msg.is_bigendian else '<')
    width, height = msg.width, msg.height
    row = width * channels * dtype.itemsize
    data = np.frombuffer(msg.data, dtype=np.uint8)
    if msg.step < row or data.size < msg.step * height:
        raise ValueError(f'{data.size} bytes do not hold {height} rows of step {msg.step} '
                         f'({width} x {msg.encoding})')
    rows = data[:msg.step * height].reshape(height, msg.step)[:, :row]
    pixels = np.ascontiguousarray(rows).view(dtype).reshape(height, width, channels)
    if kind != 'u1':
        values = pixels.astype(np.float64)
        finite = values[np.isfinite(values)]
        low, high = (finite.min(), finite.max()) if finite.size else (0.0, 0.0)
        scaled = (values - low) * (255.0 / (high - low)) if high > low else values * 0
        pixels = np.nan_to_num(scaled).clip(0, 255).astype(np.uint8)
    rgba = np.empty((height, width, 4), dtype=np.uint8)
    rgba[..., 3] = 255
    if channels == 1:
        rgba[..., :3] = pixels
    elif msg.encoding.startswith('bgr'):
        rgba[..., :3] = pixels[..., 2::-1]
    else:
        rgba[..., :3] = pixels[..., :3]
    if channels == 4:
        rgba[..., 3] = pixels[..., 3]
    return rgba.tobytes(), {'width': width, 'height': height, 'encoding': msg.encoding}


def _map_palette() -> Any:
    """rviz's "map" colour scheme, indexed by a cell's value as uint8: 0 (free) to 100
    (occupied) white to black, 101-127 green and 128-254 red to yellow (values a map should
    not hold), 255 (-1, unknown) grey-green."""
    import numpy as np
    palette = np.zeros((256, 4), dtype=np.uint8)
    palette[:, 3] = 255
    grey = 255 - (np.arange(101) * 255) // 100
    palette[:101, :3] = grey[:, None]
    palette[101:128] = (0, 255, 0, 255)
    palette[128:255, 0] = 255
    palette[128:255, 1] = (np.arange(127) * 255) // 126
    palette[255] = (0x70, 0x89, 0x86, 255)
    return palette


def _costmap_palette() -> Any:
    """rviz's "costmap" colour scheme: 0 (free) fully transparent, 1-98 blue to red, 99
    (inscribed) cyan, 100 (lethal) purple, 101-127 green and 128-254 red to yellow (not
    costs), 255 (-1, unknown) grey-green as in "map"."""
    import numpy as np
    palette = _map_palette()
    palette[0] = (0, 0, 0, 0)
    ramp = (np.arange(1, 99) * 255) // 100
    palette[1:99, 0], palette[1:99, 1], palette[1:99, 2] = ramp, 0, 255 - ramp
    palette[99] = (0, 255, 255, 255)
    palette[100] = (255, 0, 255, 255)
    return palette


def _raw_palette() -> Any:
    """rviz's "raw" colour scheme: the cell's byte as a grey level, opaque."""
    import numpy as np
    palette = np.full((256, 4), 255, dtype=np.uint8)
    palette[:, :3] = np.arange(256, dtype=np.uint8)[:, None]
    return palette


MAP_SCHEMES = {'map': _map_palette, 'costmap': _costmap_palette, 'raw': _raw_palette}


def encode_map(msg: Any, scheme: str = 'map') -> tuple[bytes, dict]:
    """nav_msgs/OccupancyGrid -> RGBA bytes, row 0 at the origin, in one of rviz's colour
    schemes (MAP_SCHEMES); the meta gives the size, resolution and the origin's pose in the
    map's frame."""
    import numpy as np
    width, height = msg.info.width, msg.info.height
    cells = np.asarray(msg.data, dtype=np.int8).view(np.uint8)
    if cells.size != width * height:
        raise ValueError(f'data holds {cells.size} cells, width * height is {width * height}')
    p, q = msg.info.origin.position, msg.info.origin.orientation
    return MAP_SCHEMES[scheme]()[cells].tobytes(), {
        'width': width, 'height': height, 'resolution': msg.info.resolution,
        'position': [p.x, p.y, p.z], 'orientation': [q.x, q.y, q.z, q.w]}
