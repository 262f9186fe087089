"""`ros2 run mujoco_sim world_to_map <world> -o <name> [--resolution 0.05] [--height 0.145]
[--start X Y]`: a MuJoCo world's static obstacles as a Nav2 map (`<name>.yaml` + `<name>.pgm`).

The world is compiled alone (no robot), and every geom welded to the world (no joint on the
way up to it) that reaches through the lidar's plane at `height` is drawn occupied: boxes,
cylinders, spheres, capsules and ellipsoids, at any position and rotation. The ground plane
and meshes are not drawn. Cells reachable from `start` without crossing an obstacle are free;
the rest (outside the walls, inside closed rooms) is unknown. The files are what Nav2's
map_saver writes in trinary mode: P5 PGM (254 free, 0 occupied, 205 unknown, row 0 the
largest y) and the YAML map_server loads.
"""

from __future__ import annotations

import argparse
import sys
from collections import deque
from pathlib import Path

import mujoco
import numpy as np

FREE, OCCUPIED, UNKNOWN = 254, 0, 205
MARGIN = 0.5  # m of map around the obstacles' extent
DRAWN = {int(mujoco.mjtGeom.mjGEOM_BOX): 'box', int(mujoco.mjtGeom.mjGEOM_CYLINDER): 'cylinder',
         int(mujoco.mjtGeom.mjGEOM_SPHERE): 'sphere',
         int(mujoco.mjtGeom.mjGEOM_CAPSULE): 'capsule',
         int(mujoco.mjtGeom.mjGEOM_ELLIPSOID): 'ellipsoid'}


class MapError(ValueError):
    """Input the tool cannot use; str() is one line naming the field."""


def resolve_world(name: str) -> Path:
    """A path as given, else a file of the package's worlds/ folder."""
    path = Path(name)
    if path.is_file():
        return path
    if not path.is_absolute():
        try:
            from ament_index_python.packages import get_package_share_directory
            installed = Path(get_package_share_directory('mujoco_sim')) / 'worlds' / name
            if installed.is_file():
                return installed
        except (ImportError, LookupError):
            pass
    raise MapError(f"world '{name}' does not exist (a path, or a file of mujoco_sim's "
                   'worlds/ folder)')


def _inside(kind: str, local: np.ndarray, size: np.ndarray) -> np.ndarray:
    """Which points (N x 3, in the geom's frame) are inside the geom."""
    x, y, z = local[:, 0], local[:, 1], local[:, 2]
    eps = 1e-9
    if kind == 'box':
        return (np.abs(x) <= size[0] + eps) & (np.abs(y) <= size[1] + eps) & \
            (np.abs(z) <= size[2] + eps)
    if kind == 'cylinder':
        return (x * x + y * y <= size[0] ** 2 + eps) & (np.abs(z) <= size[1] + eps)
    if kind == 'sphere':
        return x * x + y * y + z * z <= size[0] ** 2 + eps
    if kind == 'capsule':
        along = np.clip(z, -size[1], size[1])
        return x * x + y * y + (z - along) ** 2 <= size[0] ** 2 + eps
    return (x / size[0]) ** 2 + (y / size[1]) ** 2 + (z / size[2]) ** 2 <= 1 + eps


def static_geoms(world: Path, height: float) -> list[tuple[str, np.ndarray, np.ndarray,
                                                             np.ndarray]]:
    """(kind, centre, rotation, size) of every world-welded geom crossing z = height."""
    try:
        model = mujoco.MjModel.from_xml_path(str(world))
    except ValueError as error:
        raise MapError(f"world '{world}' does not compile: {' '.join(str(error).split())}") \
            from None
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    found = []
    for g in range(model.ngeom):
        kind = DRAWN.get(int(model.geom_type[g]))
        if kind is None or model.body_weldid[model.geom_bodyid[g]] != 0:
            continue  # the ground, meshes, and anything that can move
        centre, rotation = data.geom_xpos[g].copy(), data.geom_xmat[g].reshape(3, 3).copy()
        bottom, top = centre[2] - model.geom_rbound[g], centre[2] + model.geom_rbound[g]
        if bottom <= height <= top:  # a quick bound; the cells test the exact shape
            found.append((kind, centre, rotation, model.geom_size[g].copy()))
    return found


def rasterise(geoms, resolution: float, height: float,
              start: tuple[float, float]) -> tuple[np.ndarray, tuple[float, float]]:
    """The map image (row 0 = largest y) and its origin (x, y of the lower-left corner)."""
    if not geoms:
        raise MapError(f'the world has no static box, cylinder, sphere, capsule or ellipsoid '
                       f'crossing height {height:g} m: nothing to map')
    reach = np.array([[c[0] - np.abs(r[0]) @ s3(k, s), c[0] + np.abs(r[0]) @ s3(k, s),
                       c[1] - np.abs(r[1]) @ s3(k, s), c[1] + np.abs(r[1]) @ s3(k, s)]
                      for k, c, r, s in geoms])
    x0 = np.floor((min(reach[:, 0].min(), start[0]) - MARGIN) / resolution) * resolution
    y0 = np.floor((min(reach[:, 2].min(), start[1]) - MARGIN) / resolution) * resolution
    width = int(np.ceil((max(reach[:, 1].max(), start[0]) + MARGIN - x0) / resolution))
    rows = int(np.ceil((max(reach[:, 3].max(), start[1]) + MARGIN - y0) / resolution))
    # A cell is occupied when any of 3 x 3 points on it (corners, edge midpoints, centre)
    # is inside an obstacle: a wall's face on a cell's edge marks that cell.
    xs = x0 + resolution / 2 * np.arange(2 * width + 1)
    ys = y0 + resolution / 2 * np.arange(2 * rows + 1)
    gx, gy = np.meshgrid(xs, ys)
    points = np.stack([gx.ravel(), gy.ravel(), np.full(gx.size, height)], axis=1)
    hit = np.zeros(gx.size, dtype=bool)
    for kind, centre, rotation, size in geoms:
        hit |= _inside(kind, (points - centre) @ rotation, size)
    hit = hit.reshape(gy.shape)
    occupied = np.zeros((rows, width), dtype=bool)  # row 0 = smallest y for now
    for dy in range(3):
        for dx in range(3):
            occupied |= hit[dy:dy + 2 * rows:2, dx:dx + 2 * width:2]
    col = int((start[0] - x0) / resolution)
    row = int((start[1] - y0) / resolution)
    if occupied[row, col]:
        raise MapError(f'start ({start[0]:g}, {start[1]:g}) is inside an obstacle; allowed: '
                       'a free point from which the free space is flooded')
    free = np.zeros_like(occupied)
    free[row, col] = True
    queue = deque([(row, col)])
    while queue:
        r, c = queue.popleft()
        for nr, nc in ((r + 1, c), (r - 1, c), (r, c + 1), (r, c - 1)):
            if 0 <= nr < rows and 0 <= nc < width and not occupied[nr, nc] \
                    and not free[nr, nc]:
                free[nr, nc] = True
                queue.append((nr, nc))
    image = np.full((rows, width), UNKNOWN, dtype=np.uint8)
    image[free] = FREE
    image[occupied] = OCCUPIED
    return image[::-1].copy(), (float(x0), float(y0))


def s3(kind: str, size: np.ndarray) -> np.ndarray:
    """The half extents of the geom's bounding box in its own frame."""
    if kind in ('box', 'ellipsoid'):
        return size[:3]
    if kind == 'cylinder':
        return np.array([size[0], size[0], size[1]])
    if kind == 'capsule':
        return np.array([size[0], size[0], size[1] + size[0]])
    return np.array([size[0]] * 3)


def write_map(image: np.ndarray, origin: tuple[float, float], resolution: float,
              name: str) -> tuple[Path, Path]:
    """`<name>.pgm` and `<name>.yaml` as Nav2's map_saver writes them in trinary mode."""
    pgm, yaml = Path(f'{name}.pgm'), Path(f'{name}.yaml')
    rows, width = image.shape
    header = f'P5\n# CREATOR: world_to_map {resolution:.3f} m/pix\n{width} {rows}\n255\n'
    pgm.write_bytes(header.encode() + image.tobytes())
    # free_thresh 0.196, as map_saver writes for trinary maps: 205 (unknown) reads as
    # 1 - 205/255 = 0.19608, above it; with 0.25 map_server would load unknown as free.
    yaml.write_text(f'image: {pgm.name}\nmode: trinary\nresolution: {resolution:.3f}\n'
                    f'origin: [{origin[0]:.3f}, {origin[1]:.3f}, 0]\nnegate: 0\n'
                    'occupied_thresh: 0.65\nfree_thresh: 0.196\n')
    return pgm, yaml


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog='world_to_map', description="A MuJoCo world's static obstacles at the lidar's "
        'height as a Nav2 map (<name>.yaml + <name>.pgm).')
    parser.add_argument('world', help="an MJCF file, or a file of mujoco_sim's worlds/ folder")
    parser.add_argument('-o', '--output', required=True, metavar='NAME',
                        help='writes NAME.yaml and NAME.pgm')
    parser.add_argument('--resolution', type=float, default=0.05, help='m per cell')
    parser.add_argument('--height', type=float, default=0.145,
                        help="the lidar's plane above the ground, m (the diffbot's: 0.145)")
    parser.add_argument('--start', type=float, nargs=2, default=(0.0, 0.0), metavar=('X', 'Y'),
                        help='a free point: the free space is what is reachable from it')
    args = parser.parse_args(argv)
    try:
        if not 0.005 <= args.resolution <= 1.0:
            raise MapError(f'resolution is {args.resolution:g}; allowed: 0.005 to 1.0 m')
        if not 0.0 < args.height < 100.0:
            raise MapError(f'height is {args.height:g}; allowed: more than 0, less than 100 m')
        if not all(np.isfinite(args.start)):
            raise MapError('start must be two finite numbers')
        world = resolve_world(args.world)
        image, origin = rasterise(static_geoms(world, args.height), args.resolution,
                                  args.height, tuple(args.start))
        if not Path(args.output).parent.is_dir():
            raise MapError(f"output '{args.output}': folder "
                           f"'{Path(args.output).parent}' does not exist")
        pgm, yaml = write_map(image, origin, args.resolution, args.output)
    except MapError as error:
        print(f'world_to_map: error: {error}', file=sys.stderr)
        return 1
    rows, width = image.shape
    print(f'Wrote {yaml} and {pgm}: {width} x {rows} cells at {args.resolution:g} m, origin '
          f'({origin[0]:.3f}, {origin[1]:.3f}); {int((image == OCCUPIED).sum())} occupied, '
          f'{int((image == FREE).sum())} free, {int((image == UNKNOWN).sum())} unknown')
    return 0


if __name__ == '__main__':
    sys.exit(main())
