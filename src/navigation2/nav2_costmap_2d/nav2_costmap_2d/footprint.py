"""Footprint helpers of nav2_costmap_2d/footprint.hpp: parse, pad, radii, transform.

A footprint is a list of (x, y) vertices in the robot frame. Nav2 params give it as the
string "[[x, y], [x, y], ...]" (`footprint`) or as `robot_radius`, for which Nav2 uses a
16-gon; its inscribed radius (the inflation layer's) is the distance to the nearest edge.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

Point = tuple[float, float]

# A number as C++'s `stream >> float` reads one at the start of the remaining text.
_NUMBER = re.compile(r'[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?')


class FootprintError(ValueError):
    """A footprint string Nav2 would refuse; the message is one line naming the problem."""


def parse_vvf(text: str) -> list[list[float]]:
    """nav2_util::parseVVF: "[[1.0, 2.0], [3.3, 4.4, 5.5], ...]" -> lists of floats."""
    result: list[list[float]] = []
    current: list[float] = []
    depth = 0
    i = 0
    while i < len(text):
        char = text[i]
        if char == '[':
            depth += 1
            if depth > 2:
                raise FootprintError('Array depth greater than 2')
            current = []
            i += 1
        elif char == ']':
            depth -= 1
            if depth < 0:
                raise FootprintError('More close ] than open [')
            if depth == 1:
                result.append(current)
            i += 1
        elif char in ', \t':
            i += 1
        else:
            if depth != 2:
                raise FootprintError(f"Numbers at depth other than 2. Char was '{char}'.")
            match = _NUMBER.match(text, i)
            if match is None:
                raise FootprintError(f"Expected a number. Char was '{char}'.")
            current.append(float(match.group()))
            i = match.end()
    if depth != 0:
        raise FootprintError('Unterminated vector string.')
    return result


def make_footprint_from_string(text: str) -> list[Point]:
    """The footprint of a `footprint` parameter; FootprintError (one line) when malformed."""
    try:
        vvf = parse_vvf(text)
    except FootprintError as error:
        raise FootprintError(
            f"Error parsing footprint parameter: '{error}' (footprint was '{text}')") from None
    if len(vvf) < 3:
        raise FootprintError('You must specify at least three points for the robot footprint, '
                             f"got {len(vvf)} (footprint was '{text}')")
    for point in vvf:
        if len(point) != 2:
            raise FootprintError('Points in the footprint specification must be pairs of '
                                 f'numbers. Found a point with {len(point)} numbers.')
    return [(point[0], point[1]) for point in vvf]


def make_footprint_from_radius(radius: float) -> list[Point]:
    """Nav2's circular footprint: 16 vertices on the circle."""
    return [(math.cos(i * 2 * math.pi / 16) * radius, math.sin(i * 2 * math.pi / 16) * radius)
            for i in range(16)]


def _sign0(value: float) -> float:
    return 1.0 if value > 0 else (-1.0 if value < 0 else 0.0)


def pad_footprint(footprint: Sequence[Point], padding: float) -> list[Point]:
    """Each vertex moved outward by padding along x and y (upstream's padFootprint)."""
    return [(x + _sign0(x) * padding, y + _sign0(y) * padding) for x, y in footprint]


def _distance_to_segment(x0: float, y0: float, x1: float, y1: float) -> float:
    """Distance from the origin to the segment (x0, y0)-(x1, y1)."""
    cx, cy = x1 - x0, y1 - y0
    len_sq = cx * cx + cy * cy
    t = (-x0 * cx - y0 * cy) / len_sq if len_sq > 0 else 0.0
    t = min(1.0, max(0.0, t))
    return math.hypot(x0 + t * cx, y0 + t * cy)


def calculate_min_and_max_distances(footprint: Sequence[Point]) -> tuple[float, float]:
    """(inscribed, circumscribed) radius: nearest and farthest vertex or edge from the centre."""
    if len(footprint) <= 2:
        return math.inf, 0.0
    min_dist, max_dist = math.inf, 0.0
    for (x0, y0), (x1, y1) in zip(footprint, [*footprint[1:], footprint[0]], strict=True):
        vertex = math.hypot(x0, y0)
        edge = _distance_to_segment(x0, y0, x1, y1)
        min_dist = min(min_dist, vertex, edge)
        max_dist = max(max_dist, vertex, edge)
    return min_dist, max_dist


def transform_footprint(x: float, y: float, theta: float,
                        footprint: Sequence[Point]) -> list[Point]:
    """The footprint placed at pose (x, y, theta)."""
    c, s = math.cos(theta), math.sin(theta)
    return [(x + px * c - py * s, y + px * s + py * c) for px, py in footprint]


def footprint_from_parameters(footprint: str, robot_radius: float,
                              footprint_padding: float = 0.01) -> tuple[list[Point], bool]:
    """Costmap2DROS' choice: (padded footprint, used_radius).

    A non-empty `footprint` string wins; "" or "[]" means the robot_radius circle. A malformed
    string raises FootprintError, whose message Costmap2DROS logs before falling back to the
    radius ("The footprint parameter is invalid: ...").
    """
    if footprint not in ('', '[]'):
        return pad_footprint(make_footprint_from_string(footprint), footprint_padding), False
    return pad_footprint(make_footprint_from_radius(robot_radius), footprint_padding), True
